#include "sinew/energies/models/muscle_fiber_curves.hpp"

#include <cmath>

namespace sinew {
namespace {

// Normalized force-length bell g(s), s = λ/λ_opt − 1, symmetric about s = 0:
// plateau parabola 1 − (25/6)s² for |s| ≤ kPlateau, outer parabola
// (25/3)(|s| − kReach)² out to kReach, zero beyond. At |s| = kPlateau both
// are 1/3 with slope ∓10/3; at kReach value and slope are 0.
constexpr double kPlateau = 0.4;
constexpr double kReach = 0.6;
constexpr double kInner = 25.0 / 6.0;
constexpr double kOuter = 25.0 / 3.0;

double cube(double x) { return x * x * x; }

struct BellPoint {
    double primitive;  ///< G(s) = ∫_{−∞}^s g
    double value;      ///< g(s)
    double slope;      ///< g'(s)
};

BellPoint bell(double s)
{
    // ∫ of each piece: outer (kOuter/3)(|s| − kReach)³, plateau s − (kInner/3)s³.
    const double outer_area = kOuter / 3.0 * cube(kReach - kPlateau);
    const double plateau_area = 2.0 * kPlateau - 2.0 * kInner / 3.0 * cube(kPlateau);
    if (s <= -kReach)
        return {0.0, 0.0, 0.0};
    if (s < -kPlateau) {
        const double t = s + kReach;  // g = kOuter t², t = s + 0.6 ∈ (0, 0.2)
        return {kOuter / 3.0 * cube(t), kOuter * t * t, 2.0 * kOuter * t};
    }
    if (s <= kPlateau) {
        const double plateau = (s + kPlateau) - kInner / 3.0 * (cube(s) + cube(kPlateau));
        return {outer_area + plateau, 1.0 - kInner * s * s, -2.0 * kInner * s};
    }
    if (s < kReach) {
        const double t = s - kReach;  // g = kOuter t², t ∈ (−0.2, 0)
        return {outer_area + plateau_area + kOuter / 3.0 * (cube(t) + cube(kReach - kPlateau)), kOuter * t * t,
                2.0 * kOuter * t};
    }
    return {2.0 * outer_area + plateau_area, 0.0, 0.0};
}

} // namespace

ActiveFiberCurve::ActiveFiberCurve(double sigma_max, double lambda_opt)
    : sigma_max_(sigma_max), lambda_opt_(lambda_opt), primitive_at_rest_(bell(1.0 / lambda_opt - 1.0).primitive)
{
}

FiberCurvePoint ActiveFiberCurve::evaluate(double lambda) const
{
    // f_a = (σ_max/λ_opt) g(λ/λ_opt − 1), Φ_a = σ_max (G(λ/λ_opt − 1) − G(1/λ_opt − 1)).
    const BellPoint b = bell(lambda / lambda_opt_ - 1.0);
    const double scale = sigma_max_ / lambda_opt_;
    return {sigma_max_ * (b.primitive - primitive_at_rest_), scale * b.value, scale * b.slope / lambda_opt_};
}

std::array<double, 4> ActiveFiberCurve::break_points() const
{
    return {(1.0 - kReach) * lambda_opt_, (1.0 - kPlateau) * lambda_opt_, (1.0 + kPlateau) * lambda_opt_,
            (1.0 + kReach) * lambda_opt_};
}

PassiveFiberCurve::PassiveFiberCurve(double sigma_max, double P1, double P2, double lambda_opt, double lambda_star)
    : sigma_max_(sigma_max),
      P1_(P1),
      P2_(P2),
      lambda_opt_(lambda_opt),
      x_star_(lambda_star / lambda_opt),
      at_x_star_(exponential_piece(lambda_star / lambda_opt))
{
    primitive_at_rest_ = normalized(1.0 / lambda_opt).energy;
}

FiberCurvePoint PassiveFiberCurve::exponential_piece(double x) const
{
    // s = x − 1: h = P1 (e^{P2 s} − 1 − P2 s), h' = P1 P2 (e^{P2 s} − 1),
    // ∫₁^x h = P1 ((e^{P2 s} − 1)/P2 − s − P2 s²/2).
    const double s = x - 1.0;
    const double grown = std::expm1(P2_ * s);
    return {P1_ * (grown / P2_ - s - 0.5 * P2_ * s * s), P1_ * (grown - P2_ * s), P1_ * P2_ * grown};
}

FiberCurvePoint PassiveFiberCurve::normalized(double x) const
{
    if (x <= 1.0)
        return {};
    if (x <= x_star_)
        return exponential_piece(x);
    // Tangent line at x*: h = h* + h*'(x − x*), ∫ = H* + h*(x − x*) + h*'(x − x*)²/2.
    const double d = x - x_star_;
    const FiberCurvePoint& star = at_x_star_;
    return {star.energy + star.stress * d + 0.5 * star.stiffness * d * d, star.stress + star.stiffness * d,
            star.stiffness};
}

FiberCurvePoint PassiveFiberCurve::evaluate(double lambda) const
{
    // f_p = (σ_max/λ_opt) h(λ/λ_opt), Φ_p = σ_max (∫₁^{λ/λ_opt} h − ∫₁^{1/λ_opt} h).
    const FiberCurvePoint h = normalized(lambda / lambda_opt_);
    const double scale = sigma_max_ / lambda_opt_;
    return {sigma_max_ * (h.energy - primitive_at_rest_), scale * h.stress, scale * h.stiffness / lambda_opt_};
}

std::array<double, 2> PassiveFiberCurve::break_points() const { return {lambda_opt_, x_star_ * lambda_opt_}; }

} // namespace sinew
