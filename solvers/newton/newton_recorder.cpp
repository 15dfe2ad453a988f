#include "sinew/solvers/newton/newton_recorder.hpp"

namespace sinew {

NewtonRecorder::NewtonRecorder(const SolverOptions& options, const std::string& solver, const std::string& problem)
    : start_(Clock::now()), log_(options, solver, problem)
{
}

void NewtonRecorder::end_assembly()
{
    assembly_s_ += std::chrono::duration<double>(Clock::now() - assembly_start_).count();
}

void NewtonRecorder::record(int iteration, double objective, double violation, double dual_residual,
                            double step_norm, double alpha)
{
    HistoryRow row;
    row.iteration = iteration;
    row.objective = objective;
    row.constraint_violation = violation;
    row.dual_residual = dual_residual;
    row.step_norm = step_norm;
    row.step_length = alpha;
    row.time_s = std::chrono::duration<double>(Clock::now() - start_).count();
    if (annotate_)
        annotate_(row);
    result_.history.push_back(row);
    log_.row(row);
}

void NewtonRecorder::set_baseline(const RegularizedFactorization& factorization)
{
    baseline_ = {factorization.solver().stats(), factorization.factorizations(), factorization.factorization_seconds(),
                 factorization.solve_seconds()};
}

Result NewtonRecorder::finish(Status status, const std::string& message, const Eigen::VectorXd& x,
                              const RegularizedFactorization& factorization)
{
    const LinearSolverStats& stats = factorization.solver().stats();
    result_.status = status;
    result_.message = message;
    result_.x = x;
    result_.linear_solves = stats.solves - baseline_.stats.solves;
    result_.statistics["assembly_s"] += assembly_s_;
    result_.statistics["factorization_s"] += factorization.factorization_seconds() - baseline_.factorization_s;
    result_.statistics["linear_solve_s"] += factorization.solve_seconds() - baseline_.solve_s;
    result_.statistics["symbolic_analyses"] += stats.symbolic_analyses - baseline_.stats.symbolic_analyses;
    result_.statistics["factorizations"] += factorization.factorizations() - baseline_.factorizations;
    result_.statistics["linear_iterations"] +=
        static_cast<double>(stats.total_iterations - baseline_.stats.total_iterations);
    return result_;
}

} // namespace sinew
