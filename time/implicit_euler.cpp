#include "sinew/time/integrators.hpp"

namespace sinew {

// M(xₙ₊₁ − xₙ − h vₙ)/h² = f(xₙ₊₁): x̃ = xₙ + h vₙ, s = h².
Eigen::VectorXd ImplicitEuler::predictor() const { return state_.x + h_ * state_.v; }

Eigen::VectorXd ImplicitEuler::velocity_at(const Eigen::VectorXd& y) const { return (y - state_.x) / h_; }

void ImplicitEuler::advance(const Eigen::VectorXd& y)
{
    const Eigen::VectorXd v = velocity_at(y);  // vₙ₊₁ = (xₙ₊₁ − xₙ)/h
    state_.a = (v - state_.v) / h_;
    state_.v = v;
    state_.x = y;
}

} // namespace sinew
