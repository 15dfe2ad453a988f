#include "sinew/time/integrators.hpp"

namespace sinew {

// Eliminating vₙ₊₁ from the two BDF2 equations gives
//   xₙ₊₁ − x̃ = (4/9) h² aₙ₊₁,  x̃ = 4/3 xₙ − 1/3 xₙ₋₁ + 2/3 h (4/3 vₙ − 1/3 vₙ₋₁),
// so s = 4/9 h², and vₙ₊₁ = (3/(2h)) (xₙ₊₁ − 4/3 xₙ + 1/3 xₙ₋₁). Until a
// previous state exists (the first step) the step is implicit Euler's.

void Bdf2::start(const TimeState& initial)
{
    TimeIntegrator::start(initial);
    has_previous_ = false;
}

Eigen::VectorXd Bdf2::predictor() const
{
    if (!has_previous_)
        return state_.x + h_ * state_.v;
    return (4.0 / 3.0) * state_.x - (1.0 / 3.0) * previous_.x +
           (2.0 / 3.0) * h_ * ((4.0 / 3.0) * state_.v - (1.0 / 3.0) * previous_.v);
}

double Bdf2::force_scaling() const { return has_previous_ ? (4.0 / 9.0) * h_ * h_ : h_ * h_; }

double Bdf2::velocity_slope() const { return has_previous_ ? 1.5 / h_ : 1.0 / h_; }

Eigen::VectorXd Bdf2::velocity_at(const Eigen::VectorXd& y) const
{
    if (!has_previous_)
        return (y - state_.x) / h_;
    return (1.5 / h_) * (y - (4.0 / 3.0) * state_.x + (1.0 / 3.0) * previous_.x);
}

void Bdf2::advance(const Eigen::VectorXd& y)
{
    const Eigen::VectorXd v = velocity_at(y);
    TimeState next{y, v, (y - predictor()) / force_scaling()};  // aₙ₊₁ = (y − x̃)/s
    previous_ = state_;
    state_ = std::move(next);
    has_previous_ = true;
}

} // namespace sinew
