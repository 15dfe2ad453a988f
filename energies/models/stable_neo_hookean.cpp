#include "sinew/energies/models/stable_neo_hookean.hpp"

#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/isotropic_batch.hpp"

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

namespace {

/// ψ from I_C = ‖F‖² and J = det F.
template <typename T>
T stable_neo_hookean_energy(double mu, double lambda_stable, const T& squared_norm, const T& J)
{
    // ψ = μ/2 (I_C − 3) − μ (J − 1) + λ'/2 (J − 1)²,  I_C = ‖F‖²  (Smith et al. 2018, without the log term),
    // the last two terms as (J − 1)(λ'/2 (J − 1) − μ) so that |J| = ∞ gives +∞, not ∞ − ∞.
    return (0.5 * mu) * (squared_norm - 3.0) + (J - 1.0) * ((0.5 * lambda_stable) * (J - 1.0) - mu);
}

/// ψ, P and the analytic eigensystem of ∂P/∂F at lanes of F = U Σ Vᵀ (isotropic_batch.hpp).
template <typename T>
IsotropicResponse<T> stable_neo_hookean_response(double mu, double lambda_stable, const Matrix3<T>& F,
                                                 const detail::Svd3<T>& svd)
{
    // ∂J/∂F = cof F, columns f₁ × f₂, f₂ × f₀, f₀ × f₁; J = f₀ · (f₁ × f₂).
    const Matrix3<T> dJdF = determinant_gradient(F);
    const T J = dot(F.col[0], dJdF.col[0]);
    const T c = lambda_stable * (J - 1.0) - mu;  // c = λ'(J − 1) − μ
    IsotropicResponse<T> out;
    out.psi = stable_neo_hookean_energy(mu, lambda_stable,
                                        dot(F.col[0], F.col[0]) + dot(F.col[1], F.col[1]) + dot(F.col[2], F.col[2]), J);
    for (int j = 0; j < 3; ++j)
        out.P.col[j] = T(mu) * F.col[j] + c * dJdF.col[j];  // P = μF + (λ'(J − 1) − μ) ∂J/∂F
    // The paper's analytic eigensystem (Smith et al. 2018; seed 000 §4.5 block
    // structure): with J_i = ∂J/∂σ_i = Π_{m≠i} σ_m and ∂²J/∂σ_i∂σ_j = σ_k (i ≠ j,
    // k the third), twist_k = μ + c σ_k, flip_k = μ − c σ_k, scaling block
    // μI + λ' ∇J∇Jᵀ + c ∂²J/∂σ².
    const Vector3<T>& s = svd.sigma;
    for (int k = 0; k < 3; ++k) {
        out.twist[k] = mu + c * s[k];
        out.flip[k] = mu - c * s[k];
    }
    out.scaling = scaling_block(T(mu), T(lambda_stable), c, s);
    return out;
}

} // namespace

double StableNeoHookean::energy(const Deformation& F, const Point&) const
{
    return evaluate_exact(F, nullptr, nullptr);
}

double StableNeoHookean::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                  Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

void StableNeoHookean::evaluate_batch(int count, const Deformation* F, const Point*, double* psi, Stress* P,
                                      Stiffness* dPdF, Projection projection) const
{
    if (dPdF && projection == Projection::clamp) {
        // The clamped eigensystem needs the SVD: all of it in SIMD lanes.
        evaluate_isotropic_batch(count, F, psi, P, dPdF, projection, [&](const auto& Fk, const auto& svd) {
            return stable_neo_hookean_response(mu_, lambda_stable_, Fk, svd);
        });
        return;
    }
    for (int k = 0; k < count; ++k)
        psi[k] = evaluate_exact(F[k], P ? P + k : nullptr, dPdF ? dPdF + k : nullptr);
}

double StableNeoHookean::evaluate_exact(const Deformation& F, Stress* P, Stiffness* dPdF) const
{
    const Eigen::Matrix3d dJdF = determinant_gradient(F);  // ∂J/∂F = cof F
    const double J = F.col(0).dot(dJdF.col(0));           // J = f₀ · (f₁ × f₂)
    // Coefficient of ∂J/∂F in P and of ∂²J/∂F² in ∂P/∂F: c = λ'(J − 1) − μ.
    const double c = lambda_stable_ * (J - 1.0) - mu_;
    if (P)
        *P = mu_ * F + c * dJdF;  // P = μF + (λ'(J − 1) − μ) ∂J/∂F
    if (dPdF) {
        // ∂P/∂F = μ𝕀 + λ' vec(∂J/∂F) vec(∂J/∂F)ᵀ + c ∂²J/∂F²
        Stiffness& H = *dPdF;
        const Eigen::Map<const Eigen::Matrix<double, 9, 1>> g(dJdF.data());
        H.noalias() = lambda_stable_ * g * g.transpose();
        H.diagonal().array() += mu_;
        add_determinant_hessian(c, F, H);
    }
    return stable_neo_hookean_energy(mu_, lambda_stable_, F.squaredNorm(), J);
}

} // namespace sinew
