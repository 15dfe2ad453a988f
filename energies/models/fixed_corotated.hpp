#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// Fixed corotated elasticity (Stomakhin, Howes, Schroeder, Teran 2012,
/// "Energetically consistent invertible elasticity"):
///
///     ψ = μ ‖F − R‖² + λ/2 (J − 1)² = μ Σᵢ (σᵢ − 1)² + λ/2 (J − 1)²,
///
/// R = U Vᵀ from the rotation-variant SVD (σ₂ < 0 for inverted F), so ψ is
/// defined and finite for every F. Docs: docs/energies.md (fixed-corotated).
class FixedCorotated final : public Model3d {
public:
    static constexpr const char* kName = "fixed-corotated";

    /// Smallest value of σ_i + σ_j used in ∂R/∂F = Σ 2/(σ_i + σ_j) t tᵀ: at
    /// σ_i + σ_j = 0 R is not differentiable and ∂P/∂F would be infinite, so
    /// below this ∂P/∂F is a finite stand-in, not the derivative.
    static constexpr double kMinSingularValueSum = 1e-6;

    /// mu (Pa, > 0) and lambda (Pa, >= 0): the Lamé parameters (also those of the linearization).
    static std::vector<ParameterSpec> parameter_specs();

    /// From values already checked by resolve_parameters against parameter_specs().
    explicit FixedCorotated(const ParameterValues& parameters);

    std::string name() const override { return kName; }
    double energy(const Deformation& F, const Point& point) const override;
    /// ∂P/∂F analytic from the singular-space eigensystem (one 3×3 block, three
    /// twist and three flip modes, ∂R/∂F in the twist eigenvalues);
    /// Projection::clamp clamps its negative eigenvalues. One SVD either way.
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;
    /// Everything in SIMD lanes (isotropic_batch.hpp).
    void evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                        Stiffness* dPdF, Projection projection) const override;

private:
    double mu_;      ///< μ, Pa
    double lambda_;  ///< λ, Pa
};

} // namespace sinew
