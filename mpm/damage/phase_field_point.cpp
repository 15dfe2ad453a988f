#include "sinew/mpm/damage/phase_field_point.hpp"

#include <cmath>

namespace sinew {
namespace {

constexpr double kUnitTolerance = 1e-9;

template <int Dim>
bool unit(const Eigen::Matrix<double, Dim, 1>& a)
{
    return a.allFinite() && std::abs(a.norm() - 1.0) <= kUnitTolerance;
}

bool positive(double value) { return std::isfinite(value) && value > 0.0; }

bool weight(double value) { return std::isfinite(value) && value >= -1.0; }

} // namespace

template <int Dim>
std::string phase_field_point_error(const PhaseFieldPoint<Dim>& point)
{
    if (point.directors_used != 1 && point.directors_used != 2)
        return "directors_used must be 1 (transverse isotropy) or 2 (orthotropy)";
    if (Dim == 2 && point.directors_used == 2)
        return "orthotropy (two directors) needs 3D";
    if (!unit(point.director1))
        return "director a1 must be a finite unit vector";
    if (!weight(point.weight1))
        return "weight of a1 must be finite and >= -1";
    if (point.directors_used == 2) {
        if (!unit(point.director2))
            return "director a2 must be a finite unit vector";
        if (std::abs(point.director1.dot(point.director2)) > kUnitTolerance)
            return "directors a1 and a2 must be orthogonal";
        if (!weight(point.weight2))
            return "weight of a2 must be finite and >= -1";
    }
    if (!positive(point.sigma_crit))
        return "sigma_crit must be finite and positive";
    if (!positive(point.eta))
        return "eta must be finite and positive";
    if (!(std::isfinite(point.zeta) && point.zeta >= 0.0))
        return "zeta must be finite and >= 0";
    if (!positive(point.l0))
        return "l0 must be finite and positive";
    if (!(std::isfinite(point.history) && point.history >= 0.0))
        return "the driving force's history must be finite and >= 0";
    return {};
}

template std::string phase_field_point_error<2>(const PhaseFieldPoint<2>&);
template std::string phase_field_point_error<3>(const PhaseFieldPoint<3>&);

} // namespace sinew
