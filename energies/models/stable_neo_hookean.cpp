#include "sinew/energies/models/stable_neo_hookean.hpp"

#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/isotropic_stiffness_modes.hpp"
#include "sinew/energies/models/svd_batch.hpp"

namespace sinew {

std::vector<ParameterSpec> StableNeoHookean::parameter_specs()
{
    // {name, default, unit, description, lower, upper, lower_exclusive, choices}
    const ParameterSpec mu{"mu", 1e4, "Pa", "shear modulus μ of the linearization at rest", 0.0, 1e300, true, {}};
    const ParameterSpec lambda{"lambda", 1e5, "Pa", "Lamé's first parameter λ of the linearization at rest",
                               0.0, 1e300, false, {}};
    return {mu, lambda};
}

StableNeoHookean::StableNeoHookean(const ParameterValues& parameters)
    : mu_(parameters.at("mu")), lambda_stable_(parameters.at("lambda") + parameters.at("mu"))
{
}

double StableNeoHookean::energy_of(double squared_norm, double J) const
{
    // ψ = μ/2 (I_C − 3) − μ (J − 1) + λ'/2 (J − 1)²,  I_C = ‖F‖²  (Smith et al. 2018, without the log term),
    // the last two terms as (J − 1)(λ'/2 (J − 1) − μ) so that |J| = ∞ gives +∞, not ∞ − ∞.
    return 0.5 * mu_ * (squared_norm - 3.0) + (J - 1.0) * (0.5 * lambda_stable_ * (J - 1.0) - mu_);
}

double StableNeoHookean::energy(const Deformation& F, const Point&) const
{
    return energy_of(F.squaredNorm(), F.determinant());
}

double StableNeoHookean::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                  Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

void StableNeoHookean::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                                      Stiffness* dPdF, Projection projection) const
{
    const bool needs_svd = dPdF && projection == Projection::clamp;
    evaluate_with_svds(count, F, points, psi, P, dPdF, needs_svd,
                       [&](const Deformation& Fk, const RotationVariantSvd<3>* svd, const Point&, Stress* Pk,
                           Stiffness* dPdFk, DeferredRotation& deferred) {
                           return evaluate_with_svd(Fk, svd, Pk, dPdFk, projection, deferred);
                       });
}

double StableNeoHookean::evaluate_with_svd(const Deformation& F, const RotationVariantSvd<3>* known_svd, Stress* P,
                                           Stiffness* dPdF, Projection projection, DeferredRotation& deferred) const
{
    const Eigen::Matrix3d dJdF = determinant_gradient(F);  // ∂J/∂F = cof F
    const double J = F.col(0).dot(dJdF.col(0));           // J = f₀ · (f₁ × f₂)
    // Coefficient of ∂J/∂F in P and of ∂²J/∂F² in ∂P/∂F: c = λ'(J − 1) − μ.
    const double c = lambda_stable_ * (J - 1.0) - mu_;
    if (P)
        *P = mu_ * F + c * dJdF;  // P = μF + (λ'(J − 1) − μ) ∂J/∂F
    if (dPdF) {
        Stiffness& H = *dPdF;
        if (projection == Projection::clamp) {
            // The paper's analytic eigensystem (Smith et al. 2018; seed 000 §4.5
            // block structure): with J_i = ∂J/∂σ_i = Π_{m≠i} σ_m and ∂²J/∂σ_i∂σ_j = σ_k (i ≠ j, k the
            // third), twist_k = μ + c σ_k, flip_k = μ − c σ_k, scaling block μI + λ' ∇J∇Jᵀ + c ∂²J/∂σ².
            const RotationVariantSvd<3>& svd = *known_svd;
            const Eigen::Vector3d& s = svd.sigma;
            const Eigen::Vector3d dJ(s[1] * s[2], s[0] * s[2], s[0] * s[1]);
            IsotropicStiffnessSpectrum spectrum;
            spectrum.twist = Eigen::Vector3d::Constant(mu_) + c * s;
            spectrum.flip = Eigen::Vector3d::Constant(mu_) - c * s;
            spectrum.scaling = lambda_stable_ * dJ * dJ.transpose();
            spectrum.scaling.diagonal().array() += mu_;
            spectrum.scaling(0, 1) += c * s[2];
            spectrum.scaling(0, 2) += c * s[1];
            spectrum.scaling(1, 2) += c * s[0];
            spectrum.scaling(1, 0) = spectrum.scaling(0, 1);
            spectrum.scaling(2, 0) = spectrum.scaling(0, 2);
            spectrum.scaling(2, 1) = spectrum.scaling(1, 2);
            bool clamped = false;
            const IsotropicStiffnessSpectrum projected = clamp_spectrum(spectrum, clamped);
            if (clamped) {
                // ∂P/∂F = (V ⊗ U) (clamped frame blocks) (V ⊗ U)ᵀ, no exact ∂P/∂F needed.
                H.setZero();
                deferred.add(frame_of(projected));
                return energy_of(F.squaredNorm(), J);
            }
        }
        // ∂P/∂F = μ𝕀 + λ' vec(∂J/∂F) vec(∂J/∂F)ᵀ + c ∂²J/∂F²
        const Eigen::Map<const Eigen::Matrix<double, 9, 1>> g(dJdF.data());
        H.noalias() = lambda_stable_ * g * g.transpose();
        H.diagonal().array() += mu_;
        add_determinant_hessian(c, F, H);
    }
    return energy_of(F.squaredNorm(), J);
}

} // namespace sinew
