#include "sinew/solvers/newton/stagnation_watch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sinew {

StagnationWatch::StagnationWatch(int window) : window_(window)
{
    if (window < 1)
        throw std::invalid_argument("StagnationWatch: the window must hold at least one step");
    marks_.resize(static_cast<std::size_t>(window) + 1);
}

bool StagnationWatch::stagnant(double f, double gradient_norm)
{
    const std::size_t slots = marks_.size();
    const Mark* previous = recorded_ > 0 ? &marks_[static_cast<std::size_t>(recorded_ - 1) % slots] : nullptr;
    Mark& now = marks_[static_cast<std::size_t>(recorded_) % slots];
    now.f = f;
    now.best_gradient = previous ? std::min(previous->best_gradient, gradient_norm) : gradient_norm;
    ++recorded_;
    if (recorded_ < static_cast<int>(slots))
        return false;
    // The point `window` steps back sits in the slot after this one.
    const Mark& start = marks_[static_cast<std::size_t>(recorded_) % slots];
    const bool f_unchanged = start.f - now.f <= 1e-12 * std::max(1.0, std::abs(start.f));
    const bool gradient_not_halved = now.best_gradient > 0.5 * start.best_gradient;
    return f_unchanged && gradient_not_halved;
}

} // namespace sinew
