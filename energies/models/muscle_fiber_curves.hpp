#pragma once
// Fiber stress curves of the muscle model (seed 000 §4.2, §4.3.3): the
// active force-length curve and the passive exponential curve of Blemker,
// Pinsky and Delp 2005 in the C¹ form of PhysBAM's face model (Sifakis,
// Neverov, Fedkiw 2005, the code seed 000 describes), with the optimal fiber
// stretch λ_opt of Blemker et al. Each curve gives the fiber stress
// f(λ) = ∂Φ/∂λ (PhysBAM's "tension"), its slope f'(λ) and the exact energy
// primitive Φ(λ) = ∫₁^λ f. Formulas, defaults and what differs from the
// published curves: docs/energies.md (mooney-rivlin-muscle).
#include <array>

namespace sinew {

/// One fiber curve evaluated at a stretch λ.
struct FiberCurvePoint {
    double energy = 0.0;     ///< Φ(λ) = ∫₁^λ f (J/m³); Φ(1) = 0
    double stress = 0.0;     ///< f(λ) = Φ'(λ) (Pa)
    double stiffness = 0.0;  ///< f'(λ) = Φ''(λ) (Pa)
};

/// Active force-length curve at full activation, f_a(λ) = (σ_max/λ_opt) g(x),
/// x = λ/λ_opt, s = x − 1: g = 1 − (25/6)s² for |s| ≤ 0.4,
/// (25/3)(|s| − 0.6)² for 0.4 < |s| < 0.6, 0 beyond. g(1) = 1 is the peak;
/// the pieces meet with equal value and slope at |s| = 0.4 and 0.6.
class ActiveFiberCurve {
public:
    /// σ_max ≥ 0 peak isometric stress (Pa), λ_opt > 0 optimal fiber stretch.
    ActiveFiberCurve(double sigma_max, double lambda_opt);

    FiberCurvePoint evaluate(double lambda) const;

    /// Stretches where the pieces meet: λ_opt·(0.4, 0.6, 1.4, 1.6).
    std::array<double, 4> break_points() const;

private:
    double sigma_max_;
    double lambda_opt_;
    double primitive_at_rest_;  ///< ∫ g up to x = 1/λ_opt, so that Φ(1) = 0
};

/// Passive fiber curve f_p(λ) = (σ_max/λ_opt) h(x), x = λ/λ_opt, s = x − 1:
/// h = 0 for s ≤ 0 (slack), P1(e^{P2 s} − 1 − P2 s) up to x* = λ*/λ_opt, and
/// the tangent line of that at x* beyond (PhysBAM's P3 x + P4).
class PassiveFiberCurve {
public:
    /// σ_max ≥ 0 (Pa), P1 ≥ 0 and P2 > 0 (dimensionless), λ_opt > 0, λ* ≥ λ_opt
    /// the stretch where the curve turns linear.
    PassiveFiberCurve(double sigma_max, double P1, double P2, double lambda_opt, double lambda_star);

    FiberCurvePoint evaluate(double lambda) const;

    /// Stretches where the pieces meet: the slack stretch λ_opt and λ*.
    std::array<double, 2> break_points() const;

private:
    /// h, h' and ∫₁^x h on the exponential piece (x ≥ 1, no linear continuation).
    FiberCurvePoint exponential_piece(double x) const;
    /// h, h' and ∫₁^x h for any x.
    FiberCurvePoint normalized(double x) const;

    double sigma_max_;
    double P1_;
    double P2_;
    double lambda_opt_;
    double x_star_;                    ///< λ*/λ_opt
    FiberCurvePoint at_x_star_;        ///< the exponential piece at x*
    double primitive_at_rest_ = 0.0;   ///< ∫₁^{1/λ_opt} h, so that Φ(1) = 0
};

} // namespace sinew
