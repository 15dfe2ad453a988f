#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/stable_neo_hookean.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// Stable Neo-Hookean for plane F (2×2; MPM in 2D, plane triangles):
///
///     ψ = μ/2 (I_C − 2) − μ (J − 1) + λ'/2 (J − 1)²,   λ' = λ + μ,
///
/// the 3D model (stable_neo_hookean.hpp) with its parameters: P(I) = 0 and the
/// linearization at rest is linear elasticity with μ, λ in 2D as in 3D. It
/// equals the 3D model at diag(F, 1) (plane strain) for every F.
/// Docs: docs/energies.md (stable-neo-hookean).
class PlaneStableNeoHookean final : public Model2d {
public:
    static constexpr const char* kName = "stable-neo-hookean";

    /// The 3D model's: mu and lambda.
    static std::vector<ParameterSpec> parameter_specs() { return StableNeoHookean::parameter_specs(); }

    explicit PlaneStableNeoHookean(const ParameterValues& parameters);

    std::string name() const override { return kName; }
    double energy(const Deformation& F, const Point& point) const override;
    /// ∂P/∂F = μI + λ' cof F ⊗ cof F + (λ'(J − 1) − μ) ∂²J/∂F², a polynomial in
    /// F; Projection::clamp clamps its negative eigenvalues (clamp_plane_stiffness).
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;

private:
    double mu_;             ///< μ, Pa
    double lambda_stable_;  ///< λ' = λ + μ, Pa
};

} // namespace sinew
