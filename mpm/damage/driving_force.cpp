#include "sinew/mpm/damage/driving_force.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/damage/structural_tensor.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <string>

namespace sinew {

template <int Dim>
std::optional<Eigen::Matrix<double, Dim, Dim>> undegraded_cauchy_stress(const ConstitutiveModel<Dim, Dim>& model,
                                                                        const Eigen::Matrix<double, Dim, Dim>& F,
                                                                        MaterialPoint<Dim> point)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    const double J = F.determinant();
    if (!(J > 0.0) || !F.allFinite())
        return std::nullopt;
    point.damage = 0.0;
    Matrix P;
    model.evaluate(F, point, &P, nullptr, Projection::none);
    const Matrix sigma = P * F.transpose() / J;  // σ = P Fᵀ / J
    if (!sigma.allFinite())
        return std::nullopt;
    return Matrix(0.5 * (sigma + sigma.transpose()));
}

template <int Dim>
std::optional<DrivingForce<Dim>> driving_force(const ConstitutiveModel<Dim, Dim>& model,
                                               const Eigen::Matrix<double, Dim, Dim>& F,
                                               const MaterialPoint<Dim>& point, const PhaseFieldPoint<Dim>& field)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    const std::optional<Matrix> sigma = undegraded_cauchy_stress(model, F, point);
    if (!sigma)
        return std::nullopt;
    const Eigen::SelfAdjointEigenSolver<Matrix> eigen(*sigma);
    DrivingForce<Dim> force;
    // σ⁺ = Σ_a ⟨σ_a⟩ n_a n_aᵀ
    force.tension = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                    eigen.eigenvectors().transpose();
    const Matrix A = structural_tensor(field, F);
    // Φ = (Aσ⁺):(σ⁺A)/σ_c²
    force.phi = (A * force.tension).cwiseProduct(force.tension * A).sum() / (field.sigma_crit * field.sigma_crit);
    force.current = field.zeta * std::max(force.phi - 1.0, 0.0);  // ζ⟨Φ − 1⟩
    return force;
}

template <int Dim>
double critical_stress_from_stretch(const ConstitutiveModel<Dim, Dim>& model, const MaterialPoint<Dim>& point,
                                    const PhaseFieldPoint<Dim>& field, double p)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    if (!(std::isfinite(p) && p > 0.0))
        throw InputError("the stretch p that sets sigma_crit must be finite and positive, not " + std::to_string(p));
    PhaseFieldPoint<Dim> unit_field = field;
    unit_field.sigma_crit = 1.0;
    unit_field.zeta = 1.0;
    const std::optional<DrivingForce<Dim>> force =
        driving_force(model, Matrix((1.0 + p) * Matrix::Identity()), point, unit_field);
    if (!force || !(force->phi > 0.0) || !std::isfinite(force->phi))
        throw InputError("the model has no tension its structural tensor sees at the uniform stretch 1 + p = " +
                         std::to_string(1.0 + p) + ": sigma_crit cannot be set from p");
    return std::sqrt(force->phi);  // Φ(σ_c = 1) = (Aσ⁺):(σ⁺A)
}

template std::optional<Eigen::Matrix2d> undegraded_cauchy_stress<2>(const ConstitutiveModel<2, 2>&,
                                                                    const Eigen::Matrix2d&, MaterialPoint<2>);
template std::optional<Eigen::Matrix3d> undegraded_cauchy_stress<3>(const ConstitutiveModel<3, 3>&,
                                                                    const Eigen::Matrix3d&, MaterialPoint<3>);
template std::optional<DrivingForce<2>> driving_force<2>(const ConstitutiveModel<2, 2>&, const Eigen::Matrix2d&,
                                                         const MaterialPoint<2>&, const PhaseFieldPoint<2>&);
template std::optional<DrivingForce<3>> driving_force<3>(const ConstitutiveModel<3, 3>&, const Eigen::Matrix3d&,
                                                         const MaterialPoint<3>&, const PhaseFieldPoint<3>&);
template double critical_stress_from_stretch<2>(const ConstitutiveModel<2, 2>&, const MaterialPoint<2>&,
                                                const PhaseFieldPoint<2>&, double);
template double critical_stress_from_stretch<3>(const ConstitutiveModel<3, 3>&, const MaterialPoint<3>&,
                                                const PhaseFieldPoint<3>&, double);

} // namespace sinew
