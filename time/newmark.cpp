#include "sinew/time/integrators.hpp"

namespace sinew {

// xₙ₊₁ = xₙ + h vₙ + h²((½ − β) aₙ + β aₙ₊₁): x̃ = xₙ + h vₙ + (½ − β) h² aₙ,
// s = β h², aₙ₊₁ = (xₙ₊₁ − x̃)/s; vₙ₊₁ = vₙ + h((1 − γ) aₙ + γ aₙ₊₁), so
// v(y) = vₙ + (1 − γ) h aₙ + (γ h / s)(y − x̃).

Eigen::VectorXd Newmark::predictor() const
{
    return state_.x + h_ * state_.v + (0.5 - kBeta) * h_ * h_ * state_.a;
}

Eigen::VectorXd Newmark::velocity_at(const Eigen::VectorXd& y) const
{
    return state_.v + (1.0 - kGamma) * h_ * state_.a + (kGamma * h_ / force_scaling()) * (y - predictor());
}

// With β = ¼ and γ = ½ the velocity update equals vₙ₊₁ = 2(xₙ₊₁ − xₙ)/h − vₙ,
// which is taken: it does not pass through aₙ₊₁ = (y − x̃)/s, whose rounding
// (ε‖x‖/s) is (ωh)⁻² times larger relative to a than that of y − xₙ.
void Newmark::advance(const Eigen::VectorXd& y)
{
    const Eigen::VectorXd a = (y - predictor()) / force_scaling();
    state_.v = (2.0 / h_) * (y - state_.x) - state_.v;
    state_.a = a;
    state_.x = y;
}

} // namespace sinew
