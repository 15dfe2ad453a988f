#pragma once
#include "sinew/solvers/newton/regularized_factorization.hpp"
#include "sinew/solvers/progress_log.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <chrono>
#include <functional>
#include <string>

namespace sinew {

/// The history, timings, counters and final Result every Newton-type solver
/// fills the same way (DESIGN.md, "Solvers"): one HistoryRow per iteration,
/// printed by the progress log; finish() writes the Result.
class NewtonRecorder {
public:
    NewtonRecorder(const SolverOptions& options, const std::string& solver, const std::string& problem);

    /// Starts timing an evaluation of f, ∇f, c, J or ∇²L; stop with end_assembly().
    void begin_assembly() { assembly_start_ = Clock::now(); }
    void end_assembly();
    void count_evaluation(int count = 1) { result_.function_evaluations += count; }
    void set_iterations(int iterations) { result_.iterations = iterations; }
    /// A named count or total reported in Result::statistics.
    void add_statistic(const std::string& name, double amount) { result_.statistics[name] += amount; }

    /// Called on every row before it is stored: an outer loop running this
    /// solve as its subproblem writes its own objective and violation there.
    void set_row_annotation(std::function<void(HistoryRow&)> annotate) { annotate_ = std::move(annotate); }

    /// One history row: objective, constraint violation, dual residual, ‖Δx‖∞ and α.
    void record(int iteration, double objective, double violation, double dual_residual, double step_norm,
                double alpha);

    /// The Result: status, message, x, multipliers (empty: solve() estimates
    /// them), and the linear-algebra counters and times of `factorization`.
    /// Counts of `factorization` from an earlier solve (a factorization kept
    /// across solves, SolverMemory): finish() reports only this solve's.
    void set_baseline(const RegularizedFactorization& factorization);
    Result finish(Status status, const std::string& message, const Eigen::VectorXd& x,
                  const RegularizedFactorization& factorization);

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_;
    Clock::time_point assembly_start_;
    double assembly_s_ = 0.0;
    /// The factorization's counts when this solve began (set_baseline).
    struct Baseline {
        LinearSolverStats stats;
        int factorizations = 0;
        double factorization_s = 0.0;
        double solve_s = 0.0;
    } baseline_;
    ProgressLog log_;
    std::function<void(HistoryRow&)> annotate_;
    Result result_;
};

} // namespace sinew
