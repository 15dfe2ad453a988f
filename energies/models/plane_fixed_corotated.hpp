#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/fixed_corotated.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// Fixed corotated elasticity for plane F (2×2; MPM in 2D, plane triangles):
///
///     ψ = μ ‖F − R‖² + λ/2 (J − 1)²,
///
/// the 3D model (fixed_corotated.hpp) with its parameters. In 2D the rotation
/// R of the rotation-variant polar decomposition has a closed form: with
/// a = F₀₀ + F₁₁, b = F₁₀ − F₀₁ and r = √(a² + b²) = σ₁ + σ₂ (σ₂ < 0 for an
/// inverted F), R = [[a, −b], [b, a]]/r and ‖F − R‖² = ‖F‖² − 2r + 2. For F
/// with J > 0 it equals the 3D model at diag(F, 1) (plane strain).
/// Docs: docs/energies.md (fixed-corotated).
class PlaneFixedCorotated final : public Model2d {
public:
    static constexpr const char* kName = "fixed-corotated";

    /// Below this r = σ₁ + σ₂ (where R is not differentiable) ∂R/∂F uses this
    /// value: a finite stand-in, not the derivative, as in the 3D model.
    static constexpr double kMinSingularValueSum = 1e-6;

    /// The 3D model's: mu and lambda.
    static std::vector<ParameterSpec> parameter_specs() { return FixedCorotated::parameter_specs(); }

    explicit PlaneFixedCorotated(const ParameterValues& parameters);

    std::string name() const override { return kName; }
    double energy(const Deformation& F, const Point& point) const override;
    /// ∂P/∂F = 2μ(I − ∂R/∂F) + λ cof F ⊗ cof F + λ(J − 1) ∂²J/∂F², with
    /// ∂R/∂F = t tᵀ/r, t = vec(W R), W the quarter turn; Projection::clamp
    /// clamps its negative eigenvalues (clamp_plane_stiffness).
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;

private:
    double mu_;      ///< μ, Pa
    double lambda_;  ///< λ, Pa
};

} // namespace sinew
