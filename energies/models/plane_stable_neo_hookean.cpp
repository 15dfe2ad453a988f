#include "sinew/energies/models/plane_stable_neo_hookean.hpp"

#include "sinew/energies/models/plane_derivatives.hpp"

#include <limits>

namespace sinew {

PlaneStableNeoHookean::PlaneStableNeoHookean(const ParameterValues& parameters)
    : mu_(parameters.at("mu")), lambda_stable_(parameters.at("lambda") + parameters.at("mu"))
{
}

double PlaneStableNeoHookean::energy(const Deformation& F, const Point& point) const
{
    return evaluate(F, point, nullptr, nullptr, Projection::none);
}

double PlaneStableNeoHookean::evaluate(const Deformation& F, const Point&, Stress* P, Stiffness* dPdF,
                                       Projection projection) const
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double J = F.determinant();
    // ψ = μ/2 (I_C − 2) − μ(J − 1) + λ'/2 (J − 1)², the last two as (J − 1)(λ'/2 (J − 1) − μ)
    double psi = 0.5 * mu_ * (F.squaredNorm() - 2.0) + (J - 1.0) * (0.5 * lambda_stable_ * (J - 1.0) - mu_);
    if (!(psi < kInf))
        psi = kInf;
    const double c = lambda_stable_ * (J - 1.0) - mu_;  // c = λ'(J − 1) − μ
    const Eigen::Matrix2d cof = plane_determinant_gradient(F);
    if (P)
        *P = mu_ * F + c * cof;  // P = μF + (λ'(J − 1) − μ) cof F
    if (dPdF) {
        const Eigen::Map<const Eigen::Vector4d> g(cof.data());
        *dPdF = mu_ * Stiffness::Identity() + lambda_stable_ * g * g.transpose();
        add_plane_determinant_hessian(c, *dPdF);
        if (projection == Projection::clamp)
            clamp_plane_stiffness(*dPdF);
    }
    return psi;
}

} // namespace sinew
