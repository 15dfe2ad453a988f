#pragma once
// The muscle constitutive model of seed 000 (§4.2–4.5, §5.4–5.6): a
// Mooney-Rivlin matrix with a logarithmic volume term and an active/passive
// fiber response, evaluated in the SVD-diagonal frame, defined through
// inversion by a threshold on the singular values. Full account, including
// the places where the seed is wrong or ambiguous:
// docs/energies.md (mooney-rivlin-muscle).
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"
#include "sinew/energies/models/muscle_fiber_curves.hpp"

#include <string>
#include <vector>

namespace sinew {

/// How the fiber stretch is measured (seed 000 §4.3.3, WARNING).
enum class FiberStretch {
    physbam,     ///< λ̃ = |F a₀|, what PhysBAM computes (§4.3.3, §4.5.2); the default
    deviatoric,  ///< λ = J^(−1/3) |F a₀|, the note's definition (§4.2)
};

/// ψ(F) = A Ī₁ + B Ī₂ + K/2 L² + α Φ_a(λ) + Φ_p(λ) (seed 000 §4.2), with
/// Ī₁, Ī₂ the invariants of C̄ = e^(−2L/3) FᵀF, L = ln J, Φ_a, Φ_p the
/// primitives of the fiber stress curves (muscle_fiber_curves.hpp), α the
/// activation and a₀ the fiber of the material point.
///
/// Inversion (seed 000 §5.5): below the threshold c, ln σ_k inside L is
/// replaced by its tangent at c, so ψ is finite and C¹ through det F = 0 and
/// for inverted F (σ₃ < 0). With c = 0, ψ = +∞ for det F ≤ 0.
/// With sigma_max = 0 the fiber terms vanish: ψ is the Mooney-Rivlin part.
class MooneyRivlinMuscle final : public Model3d {
public:
    static constexpr const char* kName = "mooney-rivlin-muscle";

    /// A, B, K (Pa); sigma_max (Pa), lambda_opt, P1, P2, lambda_star;
    /// fiber_stretch ∈ {physbam, deviatoric}; inversion_threshold c.
    static std::vector<ParameterSpec> parameter_specs();

    /// Parameters by name; missing ones take their defaults. Invalid values,
    /// and lambda_star < lambda_opt, throw InputError naming the parameter.
    explicit MooneyRivlinMuscle(const ParameterValues& parameters);

    std::string name() const override { return kName; }

    /// ψ alone; needs an SVD only when a singular value may be below c.
    double energy(const Deformation& F, const Point& point) const override;

    /// ψ, P = U P̂ Vᵀ (§4.3, §5.4) and ∂P/∂F assembled from the SVD-frame
    /// blocks (§4.5.1) plus the fiber differential (§4.5.2, eq. 45).
    /// Projection::clamp (§5.6): the exact ∂P/∂F when it is already PSD,
    /// otherwise the eigenvalues of the 3×3 and 2×2 blocks clamped at zero
    /// and the fiber tension derivative f' raised to zero.
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;
    /// ψ is linear in α (seed 000 eq. 4, §4.2): ∂ψ/∂α = Φ_a(λ) and
    /// ∂P/∂α = f_a(λ) ∂λ/∂F, f_a the active curve at full activation, with
    /// ∂λ/∂F = (F a₀/λ̃) a₀ᵀ (physbam) or λ((F a₀)a₀ᵀ/λ̃² − ⅓ ∂L/∂F) (deviatoric,
    /// L the thresholded ln J of §5.5). Zero with sigma_max = 0.
    double activation_derivative(const Deformation& F, const Point& point, Stress* dP_dalpha) const override;
    /// kSimdLanes elements side by side (evaluate_lanes).
    void evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                        Stiffness* dPdF, Projection projection) const override;

    const ActiveFiberCurve& active_curve() const { return active_; }
    const PassiveFiberCurve& passive_curve() const { return passive_; }
    FiberStretch fiber_stretch() const { return stretch_; }
    /// c: singular values below it see ln σ continued linearly.
    double inversion_threshold() const { return threshold_; }

private:
    /// Tag of the constructor from parameters already through
    /// resolve_parameters and the cross-parameter checks.
    struct Validated {};
    MooneyRivlinMuscle(Validated, const ParameterValues& checked);

    /// ψ (and P, ∂P/∂F when not null) of F[k] for k < lanes ≤ kSimdLanes, side by
    /// side in SIMD lanes (lanes.hpp), every step but the fiber curves and
    /// exp/ln, which run lane by lane.
    void evaluate_lanes(int lanes, const Deformation* F, const Point* points, double* psi, Stress* P,
                        Stiffness* dPdF, Projection projection) const;

    double A_;  ///< Pa
    double B_;  ///< Pa
    double K_;  ///< Pa
    ActiveFiberCurve active_;
    PassiveFiberCurve passive_;
    FiberStretch stretch_;
    double threshold_;
    bool fibers_on_;  ///< false when sigma_max = 0
};

} // namespace sinew
