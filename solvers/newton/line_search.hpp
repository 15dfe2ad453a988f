#pragma once
#include <Eigen/Core>

#include <functional>
#include <string>

namespace sinew {

/// Backtracking on a merit function φ along a direction (DESIGN.md, "Solvers").
struct LineSearchSettings {
    double armijo = 1e-4;     ///< sufficient-decrease constant c₁ in (0, ½)
    int max_backtracks = 40;  ///< halvings of α before giving up
};

enum class LineSearchStatus {
    accepted,  ///< Armijo holds at α, or a round-off step was accepted
    stalled,   ///< no measurable change of φ at round-off level: nothing left to gain
    failed,    ///< no acceptable α within max_backtracks halvings
};

struct LineSearchOutcome {
    LineSearchStatus status = LineSearchStatus::failed;
    double alpha = 0.0;      ///< the last α tried (the accepted one when accepted)
    double merit = 0.0;      ///< φ(α) there
    double full_step = 0.0;  ///< φ(1), the first value tried (+∞ when undefined)
    int backtracks = 0;
};

/// Backtracking Armijo search from α = 1, halving α:
///   accept α when φ(α) is finite and φ(α) ≤ φ(0) + c₁ α φ'(0);
///   or, near a solution where the decrease falls below the round-off of φ,
///   when φ(α) ≤ φ(0) + 1e-12|φ(0)| and `roundoff_progress(α)` says another
///   measure (the gradient norm, say) improved (may be empty: never).
/// Non-finite φ (an inverted element, a failed evaluation) backs off like a
/// rejected step. φ'(0) must be negative. After max_backtracks halvings the
/// status is stalled when |φ(α) − φ(0)| ≤ 1e-14·max(1, |φ(0)|), failed otherwise.
LineSearchOutcome backtracking_line_search(const std::function<double(double alpha)>& merit, double merit_at_zero,
                                           double slope, const LineSearchSettings& settings,
                                           const std::function<bool(double alpha)>& roundoff_progress);

/// True when the accepted point x + αd equals x within round-off
/// (‖αd‖∞ ≤ 1e-15·max(1, ‖x‖∞)): the Armijo test passes with equality once
/// c₁α∇φᵀd is below the round-off of φ, so such a step makes no progress.
bool step_below_roundoff(const Eigen::VectorXd& x, const Eigen::VectorXd& accepted);

} // namespace sinew
