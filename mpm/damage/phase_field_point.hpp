#pragma once
// What a material point carries for AnisoMPM's anisotropic phase-field
// damage (seed 004 Alg. 1–2): the structural directors and weights, the
// critical stress and the damage evolution's constants, and the history of
// the driving force. The damage d itself is MaterialPoint::damage, which the
// models read.
#include <Eigen/Core>

#include <string>

namespace sinew {

template <int Dim>
struct PhaseFieldPoint {
    using Vector = Eigen::Matrix<double, Dim, 1>;

    /// Structural directors a₁ (and a₂ for orthotropy), unit, in material
    /// (rest) space; directors_used = 1 (transverse isotropy) or 2.
    Vector director1 = Vector::UnitX();
    Vector director2 = Vector::UnitY();
    int directors_used = 1;
    /// Their weights α_k ∈ [−1, ∞): A = I + Σ α_k (R a_k)(R a_k)ᵀ (Alg. 2).
    /// α = −1 removes the director's direction from the driving force.
    double weight1 = -1.0;
    double weight2 = -1.0;
    double sigma_crit = 1.0;  ///< σ_c (Pa): Φ = (Aσ⁺):(σ⁺A)/σ_c²
    double eta = 1.0;         ///< η (s): the damage's viscosity, ηḋ = (1 − d)D̃ − (d − l₀²Δd)
    double zeta = 1.0;        ///< ζ: the driving force's scale, D̃ = ζ⟨Φ − 1⟩ (0: never driven)
    double l0 = 1.0;          ///< l₀ (m): the crack's length scale (the seed's default 0.5 dx)
    double history = 0.0;     ///< D̃ᴴ: the largest driving force so far
};

/// Empty when `point` is valid; otherwise one line naming the field that is
/// not (directors finite and of unit length within 1e-9, directors_used 1 or
/// 2 (1 in 2D: orthotropy needs a third axis), a₂ ⊥ a₁ within 1e-9, weights
/// finite and ≥ −1, σ_c, η, l₀ finite and positive, ζ and history finite
/// and ≥ 0).
template <int Dim>
std::string phase_field_point_error(const PhaseFieldPoint<Dim>& point);

} // namespace sinew
