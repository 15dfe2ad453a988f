#include "sinew/energies/models/fixed_corotated.hpp"

#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/isotropic_batch.hpp"

namespace sinew {

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

namespace {

/// ψ, P and the eigensystem of ∂P/∂F at lanes of F = U Σ Vᵀ (isotropic_batch.hpp).
template <typename T>
IsotropicResponse<T> fixed_corotated_response(double mu, double lambda, const Matrix3<T>& F, const detail::Svd3<T>& svd)
{
    const Vector3<T>& s = svd.sigma;
    const T J = s[0] * s[1] * s[2];           // J = σ₀σ₁σ₂ (σ₂ < 0 when inverted)
    const T volume_factor = lambda * (J - 1.0);  // λ (J − 1)
    IsotropicResponse<T> out;
    // ψ = μ Σᵢ (σᵢ − 1)² + λ/2 (J − 1)²
    out.psi = mu * ((s[0] - 1.0) * (s[0] - 1.0) + (s[1] - 1.0) * (s[1] - 1.0) + (s[2] - 1.0) * (s[2] - 1.0)) +
              (0.5 * lambda) * (J - 1.0) * (J - 1.0);
    // P = 2μ(F − R) + λ(J − 1) ∂J/∂F, R = U Vᵀ, ∂J/∂F = cof F (columns f₁ × f₂, f₂ × f₀, f₀ × f₁).
    const Matrix3<T> dJdF = determinant_gradient(F);
    for (int j = 0; j < 3; ++j) {
        const Vector3<T> R_column = svd.V(j, 0) * svd.U.col[0] + svd.V(j, 1) * svd.U.col[1] + svd.V(j, 2) * svd.U.col[2];
        out.P.col[j] = T(2.0 * mu) * (F.col[j] - R_column) + volume_factor * dJdF.col[j];
    }
    // Eigenvalues from ψ(σ) (Smith, de Goes, Kim 2019, "Analytic eigensystems for isotropic
    // distortion energies"; seed 000 §4.5 block structure): with
    // ψ_i = ∂ψ/∂σ_i = 2μ(σ_i − 1) + λ(J − 1)J_i and J_i = Π_{m≠i} σ_m, for the pair (i, j) without k,
    //   twist_k = (ψ_i + ψ_j)/(σ_i + σ_j) = 2μ(1 − 2/(σ_i + σ_j)) + λ(J − 1)σ_k,
    //   flip_k = (ψ_i − ψ_j)/(σ_i − σ_j) = 2μ − λ(J − 1)σ_k (no division: exact at σ_i = σ_j),
    //   scaling ∂²ψ/∂σ_i∂σ_j = 2μδ_ij + λ J_i J_j + λ(J − 1)(1 − δ_ij)σ_k.
    // The twist term 2μ(1 − 2/(σ_i + σ_j)) is 2μ(𝕀 − ∂R/∂F) on that mode (Kim & Eberle, Dynamic
    // Deformables, 2020): σ_i + σ_j is floored at kMinSingularValueSum, where R is not differentiable.
    for (int k = 0; k < 3; ++k) {
        const T pair_sum = max(s[k == 0 ? 1 : 0] + s[k == 2 ? 1 : 2], T(FixedCorotated::kMinSingularValueSum));
        out.twist[k] = (2.0 * mu) * (1.0 - 2.0 / pair_sum) + volume_factor * s[k];
        out.flip[k] = 2.0 * mu - volume_factor * s[k];
    }
    out.scaling = scaling_block(T(2.0 * mu), T(lambda), volume_factor, s);
    return out;
}

} // namespace

double FixedCorotated::energy(const Deformation& F, const Point& point) const
{
    return evaluate(F, point, nullptr, nullptr, Projection::none);
}

double FixedCorotated::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

void FixedCorotated::evaluate_batch(int count, const Deformation* F, const Point*, double* psi, Stress* P,
                                    Stiffness* dPdF, Projection projection) const
{
    // ∂P/∂F, exact or clamped, is the eigensystem rotated to vec(F).
    evaluate_isotropic_batch(count, F, psi, P, dPdF, projection, [&](const auto& Fk, const auto& svd) {
        return fixed_corotated_response(mu_, lambda_, Fk, svd);
    });
}

} // namespace sinew
