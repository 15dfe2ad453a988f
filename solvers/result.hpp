#pragma once
#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace sinew {

/// How a solve ended. Only `converged` means every tolerance the user asked
/// for holds, feasibility included; x is the last (best) iterate in every case.
enum class Status {
    converged,           ///< optimality and feasibility tolerances met
    tolerance_not_met,   ///< the backend stopped on its own success test, but a requested tolerance does not hold
                         ///< at x (each within kFarFromTolerance times; beyond that the status is failed)
    max_iterations,      ///< iteration or evaluation limit reached first
    stalled,             ///< no further progress possible (round-off, tiny steps) before tolerances held
    line_search_failed,  ///< no acceptable step along the search direction
    infeasible,          ///< the solver concluded the constraints cannot be met
    numerical_error,     ///< non-finite values or a failed factorization
    user_stop,           ///< stopped by a callback or a time limit
    failed,              ///< any other failure; the message says which
};

/// A backend's success stop whose constraint violation or KKT residual exceeds
/// this multiple of its tolerance is `failed`, not `tolerance_not_met`.
inline constexpr double kFarFromTolerance = 1e3;

/// "converged", "max_iterations", … (the names used in JSON and tables).
std::string to_string(Status status);

/// One row per iteration (iteration 0 is the starting point).
struct HistoryRow {
    int iteration = 0;
    double objective = 0.0;
    double constraint_violation = 0.0;
    double dual_residual = 0.0;  ///< the solver's own measure of stationarity (NaN: not available)
    double step_norm = 0.0;      ///< ‖Δx‖∞ of the step that led here
    double step_length = 0.0;    ///< line-search fraction α of that step
    double time_s = 0.0;         ///< wall time since the solve started
    int outer_iteration = 0;     ///< the outer loop's iteration (penalty continuation, multiplier update)
};

/// The result every solver returns.
struct Result {
    std::string solver;
    std::string problem;
    Status status = Status::failed;
    std::string message;  ///< the backend's own words on how it ended

    Eigen::VectorXd x;
    /// λ of the constraints, Ipopt's sign convention: ∇f + Jᵀλ - z_L + z_U = 0.
    Eigen::VectorXd constraint_multipliers;
    Eigen::VectorXd bound_multipliers_lower;  ///< z_L >= 0
    Eigen::VectorXd bound_multipliers_upper;  ///< z_U >= 0
    /// True when the backend did not report multipliers and they were
    /// estimated afterwards by least squares on the active set.
    bool multipliers_estimated = false;

    double objective = 0.0;
    double constraint_violation = 0.0;  ///< max over bounds and constraints
    double kkt_residual = 0.0;          ///< ‖∇f + Jᵀλ - z_L + z_U‖∞ plus multiplier sign and complementarity errors
    int iterations = 0;
    int function_evaluations = 0;
    int linear_solves = -1;  ///< -1: the backend does not report it
    double time_s = 0.0;
    /// Named totals a solver chooses to report (seconds spent in assembly,
    /// factorization, …; counts such as symbolic_analyses).
    std::map<std::string, double> statistics;
    std::vector<HistoryRow> history;
};

/// Adds `part`'s counts to `total` (a run made of several solves):
/// iterations, function evaluations, linear solves (when `part` reports
/// them) and every statistic. Time, history and the end state are the
/// caller's to combine.
void add_counts(Result& total, const Result& part);

} // namespace sinew
