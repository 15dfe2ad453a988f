#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// Codimensional corotated energy of a triangle in 3D (seed 002, Z. Zhang,
/// "Codimensional Corotated Energy Note"), F 3×2:
///
///     ψ = μ ‖F − R‖² + λ/2 (J − 1)²,   J = √det(FᵀF),   F = R S (polar),
///
/// R 3×2 with orthonormal columns, S 2×2 SPD; with the thin SVD F = U Σ Vᵀ,
/// R = U Vᵀ and ψ = μ Σᵢ (σᵢ − 1)² + λ/2 (σ₀σ₁ − 1)². ψ is energy per unit rest
/// area (J/m² = N/m), so μ and λ are membrane stiffnesses in N/m: the 2D Lamé
/// parameters of the linearization at rest. ψ depends on the singular values
/// only, so it is invariant under every orthogonal Q of R³ (reflections too):
/// a 3×2 F has no inversion, a mirrored triangle is a rotated one. Finite ψ, P
/// and ∂P/∂F also at rank-deficient F (collapsed triangles).
/// Docs: docs/energies.md (codim-corotated).
class CodimensionalCorotated final : public MembraneModel {
public:
    static constexpr const char* kName = "codim-corotated";

    /// Floor of σᵢ and of σ₀ + σ₁ where ∂P/∂F divides by them (through ∂R/∂F
    /// and ∂²J/∂F², whose out-of-plane and twist eigenvalues are unbounded as
    /// the triangle collapses): ∂P/∂F is exact for σ₁ ≥ 1e-6 and finite below.
    static constexpr double kMinSingularValue = 1e-6;

    /// mu (N/m, > 0) and lambda (N/m, >= 0).
    static std::vector<ParameterSpec> parameter_specs();

    /// From values already checked by resolve_parameters against parameter_specs().
    explicit CodimensionalCorotated(const ParameterValues& parameters);

    std::string name() const override { return kName; }
    double energy(const Deformation& F, const Point& point) const override;
    /// ∂P/∂F assembled from its closed-form eigensystem in the thin SVD (a 2×2
    /// scaling block, twist, flip and two out-of-plane modes); Projection::clamp
    /// clamps those eigenvalues, the exact PSD projection (no 6×6 eigensolver).
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;

private:
    double mu_;      ///< μ, N/m
    double lambda_;  ///< λ, N/m
};

} // namespace sinew
