#include "sinew/mpm/cfl.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace sinew {
namespace {

/// The wave directions tried: axes, face diagonals, body diagonals (3D), and the fiber.
template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> wave_directions(const Eigen::Matrix<double, Dim, 1>& fiber)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    std::vector<Vector> directions;
    // every n with entries in {−1, 0, 1}, first non-zero entry positive (n and −n give one wave)
    const int count = Dim == 2 ? 9 : 27;
    for (int code = 0; code < count; ++code) {
        Vector n;
        int rest = code;
        for (int a = 0; a < Dim; ++a) {
            n[a] = static_cast<double>(rest % 3) - 1.0;
            rest /= 3;
        }
        int first = 0;
        while (first < Dim && n[first] == 0.0)
            ++first;
        if (first < Dim && n[first] > 0.0)
            directions.push_back(n.normalized());
    }
    if (fiber.norm() > 0.0)
        directions.push_back(fiber.normalized());
    return directions;
}

} // namespace

template <int Dim>
double elastic_wave_speed(const ConstitutiveModel<Dim, Dim>& model, const typename ConstitutiveModel<Dim, Dim>::Deformation& F,
                          const MaterialPoint<Dim>& point, double density)
{
    typename ConstitutiveModel<Dim, Dim>::Stiffness dPdF;
    model.evaluate(F, point, nullptr, &dPdF, Projection::none);
    double fastest = 0.0;  // ρ c²
    for (const auto& n : wave_directions<Dim>(point.fiber)) {
        Eigen::Matrix<double, Dim, Dim> A = Eigen::Matrix<double, Dim, Dim>::Zero();
        for (int i = 0; i < Dim; ++i)
            for (int k = 0; k < Dim; ++k)
                for (int j = 0; j < Dim; ++j)
                    for (int l = 0; l < Dim; ++l)
                        A(i, k) += dPdF(i + Dim * j, k + Dim * l) * n[j] * n[l];  // A_ik = ∂P_ij/∂F_kl n_j n_l
        const Eigen::Matrix<double, Dim, Dim> symmetric = 0.5 * (A + A.transpose());
        fastest = std::max(fastest, Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>>(
                                        symmetric, Eigen::EigenvaluesOnly)
                                        .eigenvalues()
                                        .maxCoeff());
    }
    return std::sqrt(fastest / density);
}

template <int Dim>
double cfl_time_step(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                     double dx, double cfl)
{
    double fastest = 0.0;  // max_p (c_p + |v_p|)
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const auto& model = *models.at(static_cast<std::size_t>(particles.material[i]));
        const double c = elastic_wave_speed<Dim>(model, particles.F[i], particles.point[i], particles.mass[i] / particles.volume[i]);
        fastest = std::max(fastest, c + particles.v[i].norm());
    }
    return fastest > 0.0 ? cfl * dx / fastest : std::numeric_limits<double>::infinity();
}

template double elastic_wave_speed<2>(const Model2d&, const Model2d::Deformation&, const MaterialPoint<2>&, double);
template double elastic_wave_speed<3>(const Model3d&, const Model3d::Deformation&, const MaterialPoint<3>&, double);
template double cfl_time_step<2>(const Particles<2>&, const std::vector<const Model2d*>&, double, double);
template double cfl_time_step<3>(const Particles<3>&, const std::vector<const Model3d*>&, double, double);

} // namespace sinew
