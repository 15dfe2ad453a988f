#include "sinew/energies/models/fixed_corotated.hpp"

#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/svd_batch.hpp"
#include "sinew/energies/models/isotropic_stiffness_modes.hpp"

#include <algorithm>

namespace sinew {
namespace {

/// ψ from the signed singular values and J = det F.
double corotated_energy(double mu, double lambda, const Eigen::Vector3d& sigma, double J)
{
    // ψ = μ Σᵢ (σᵢ − 1)² + λ/2 (J − 1)²
    return mu * (sigma.array() - 1.0).square().sum() + 0.5 * lambda * (J - 1.0) * (J - 1.0);
}

} // namespace

std::vector<ParameterSpec> FixedCorotated::parameter_specs()
{
    // {name, default, unit, description, lower, upper, lower_exclusive, choices}
    const ParameterSpec mu{"mu", 1e4, "Pa", "shear modulus μ", 0.0, 1e300, true, {}};
    const ParameterSpec lambda{"lambda", 1e5, "Pa", "Lamé's first parameter λ", 0.0, 1e300, false, {}};
    return {mu, lambda};
}

FixedCorotated::FixedCorotated(const ParameterValues& parameters)
    : mu_(parameters.at("mu")), lambda_(parameters.at("lambda"))
{
}

double FixedCorotated::energy(const Deformation& F, const Point&) const
{
    const Eigen::Vector3d sigma = fast_rotation_variant_svd(F).sigma;
    return corotated_energy(mu_, lambda_, sigma, sigma.prod());
}

double FixedCorotated::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

void FixedCorotated::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                                    Stiffness* dPdF, Projection projection) const
{
    evaluate_with_svds(count, F, points, psi, P, dPdF, true,
                       [&](const Deformation& Fk, const RotationVariantSvd<3>* svd, const Point&, Stress* Pk,
                           Stiffness* dPdFk, DeferredRotation& deferred) {
                           return evaluate_with_svd(Fk, *svd, Pk, dPdFk, projection, deferred);
                       });
}

double FixedCorotated::evaluate_with_svd(const Deformation& F, const RotationVariantSvd<3>& svd, Stress* P,
                                         Stiffness* dPdF, Projection projection, DeferredRotation& deferred) const
{
    const Eigen::Vector3d& s = svd.sigma;
    const double J = s.prod();                        // J = σ₀σ₁σ₂ (σ₂ < 0 when inverted)
    const double volume_factor = lambda_ * (J - 1.0);  // λ (J − 1)
    if (P)
        *P = 2.0 * mu_ * (F - svd.U * svd.V.transpose()) + volume_factor * determinant_gradient(F);  // P = 2μ(F − R) + λ(J − 1) ∂J/∂F
    if (dPdF) {
        Stiffness& H = *dPdF;
        // σ_i + σ_j for the pair k (the pair without k).
        const Eigen::Vector3d pair_sum(std::max(s[1] + s[2], kMinSingularValueSum),
                                       std::max(s[0] + s[2], kMinSingularValueSum),
                                       std::max(s[0] + s[1], kMinSingularValueSum));
        if (projection == Projection::clamp) {
            // Eigenvalues from ψ(σ) (Smith, de Goes, Kim 2019, "Analytic eigensystems for isotropic
            // distortion energies"; seed 000 §4.5 block structure): with
            // ψ_i = ∂ψ/∂σ_i = 2μ(σ_i − 1) + λ(J − 1)J_i and J_i = Π_{m≠i} σ_m, for the pair (i, j) without k,
            //   twist_k = (ψ_i + ψ_j)/(σ_i + σ_j) = 2μ(1 − 2/(σ_i + σ_j)) + λ(J − 1)σ_k,
            //   flip_k = (ψ_i − ψ_j)/(σ_i − σ_j) = 2μ − λ(J − 1)σ_k (no division: exact at σ_i = σ_j),
            //   scaling ∂²ψ/∂σ_i∂σ_j = 2μδ_ij + λ J_i J_j + λ(J − 1)(1 − δ_ij)σ_k.
            // ∂P/∂F is this eigensystem, clamped, rotated to vec(F).
            const Eigen::Vector3d dJ(s[1] * s[2], s[0] * s[2], s[0] * s[1]);
            IsotropicStiffnessSpectrum spectrum;
            spectrum.twist = (2.0 * mu_) * (Eigen::Vector3d::Ones() - 2.0 * pair_sum.cwiseInverse()) + volume_factor * s;
            spectrum.flip = Eigen::Vector3d::Constant(2.0 * mu_) - volume_factor * s;
            spectrum.scaling = lambda_ * dJ * dJ.transpose();
            spectrum.scaling.diagonal().array() += 2.0 * mu_;
            spectrum.scaling(0, 1) += volume_factor * s[2];
            spectrum.scaling(0, 2) += volume_factor * s[1];
            spectrum.scaling(1, 2) += volume_factor * s[0];
            spectrum.scaling(1, 0) = spectrum.scaling(0, 1);
            spectrum.scaling(2, 0) = spectrum.scaling(0, 2);
            spectrum.scaling(2, 1) = spectrum.scaling(1, 2);
            bool clamped = false;
            H.setZero();
            deferred.add(frame_of(clamp_spectrum(spectrum, clamped)));
        } else {
            // ∂P/∂F = 2μ(𝕀 − ∂R/∂F) + λ vec(∂J/∂F) vec(∂J/∂F)ᵀ + λ(J − 1) ∂²J/∂F², with
            // ∂R/∂F = Σ_k 2/(σ_i + σ_j) t_k t_kᵀ over the twist modes t_k of the pairs (i, j)
            // (Kim & Eberle, Dynamic Deformables, 2020; R does not turn along the scaling and flip modes).
            const Eigen::Matrix3d dJdF = determinant_gradient(F);
            const Eigen::Map<const Eigen::Matrix<double, 9, 1>> g(dJdF.data());
            H.noalias() = lambda_ * g * g.transpose();
            H.diagonal().array() += 2.0 * mu_;
            add_determinant_hessian(volume_factor, F, H);
            ModeCorrection rotation_part;
            rotation_part.twist = -4.0 * mu_ * pair_sum.cwiseInverse();  // −2μ ∂R/∂F
            deferred.add(frame_of(rotation_part));
        }
    }
    return corotated_energy(mu_, lambda_, s, J);
}

} // namespace sinew
