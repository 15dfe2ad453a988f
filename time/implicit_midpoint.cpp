#include "sinew/time/integrators.hpp"

namespace sinew {

// With y = xₙ₊½ = (xₙ + xₙ₊₁)/2: xₙ₊₁ − xₙ = 2(y − xₙ) = h(vₙ + vₙ₊₁)/2 gives
// vₙ₊₁ = 4(y − xₙ)/h − vₙ, and M(vₙ₊₁ − vₙ)/h = f(y) becomes
// M(y − xₙ − h vₙ/2)·4/h² = f(y): x̃ = xₙ + h vₙ/2, s = h²/4. The velocity at
// the midpoint is (vₙ + vₙ₊₁)/2 = 2(y − xₙ)/h.

Eigen::VectorXd ImplicitMidpoint::predictor() const { return state_.x + 0.5 * h_ * state_.v; }

Eigen::VectorXd ImplicitMidpoint::velocity_at(const Eigen::VectorXd& y) const { return (2.0 / h_) * (y - state_.x); }

void ImplicitMidpoint::advance(const Eigen::VectorXd& y)
{
    const Eigen::VectorXd v = (4.0 / h_) * (y - state_.x) - state_.v;
    state_.a = (v - state_.v) / h_;
    state_.v = v;
    state_.x = 2.0 * y - state_.x;
}

} // namespace sinew
