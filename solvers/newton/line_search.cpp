#include "sinew/solvers/newton/line_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {

LineSearchOutcome backtracking_line_search(const std::function<double(double alpha)>& merit, double merit_at_zero,
                                           double slope, const LineSearchSettings& settings,
                                           const std::function<bool(double alpha)>& roundoff_progress)
{
    LineSearchOutcome outcome;
    outcome.full_step = std::numeric_limits<double>::infinity();
    double alpha = 1.0;
    for (int backtracks = 0;; ++backtracks) {
        const double value = merit(alpha);
        outcome.alpha = alpha;
        outcome.merit = value;
        outcome.backtracks = backtracks;
        if (backtracks == 0)
            outcome.full_step = value;
        const bool finite = std::isfinite(value);
        // Armijo: φ(α) ≤ φ(0) + c₁ α φ'(0).
        if (finite && value <= merit_at_zero + settings.armijo * alpha * slope) {
            outcome.status = LineSearchStatus::accepted;
            return outcome;
        }
        // Round-off acceptance: φ unchanged within round-off and progress elsewhere.
        if (finite && value <= merit_at_zero + 1e-12 * std::abs(merit_at_zero) && roundoff_progress &&
            roundoff_progress(alpha)) {
            outcome.status = LineSearchStatus::accepted;
            return outcome;
        }
        if (backtracks == settings.max_backtracks) {
            const bool at_roundoff =
                finite && std::abs(value - merit_at_zero) <= 1e-14 * std::max(1.0, std::abs(merit_at_zero));
            outcome.status = at_roundoff ? LineSearchStatus::stalled : LineSearchStatus::failed;
            return outcome;
        }
        alpha *= 0.5;
    }
}

bool step_below_roundoff(const Eigen::VectorXd& x, const Eigen::VectorXd& accepted)
{
    return (accepted - x).cwiseAbs().maxCoeff() <= 1e-15 * std::max(1.0, x.cwiseAbs().maxCoeff());
}

} // namespace sinew
