#include "sinew/runs/refreshed_solve.hpp"

namespace sinew {

Result solve_with_refreshed_rows(QuasistaticProblem& problem, const std::string& solver, const SolverOptions& options)
{
    problem.refresh_constraints(problem.full_configuration(problem.starting_point()));
    Result result = solve(problem, solver, options);
    int rounds = 1, iterations = result.iterations, evaluations = result.function_evaluations;
    double time_s = result.time_s;
    Eigen::VectorXd solution = problem.full_configuration(result.x);
    while (!problem.constraint_rows_suffice(solution) && rounds < kMaxConstraintRounds) {
        problem.refresh_constraints(solution);
        problem.set_starting_configuration(solution);
        result = solve(problem, solver, options);
        ++rounds;
        iterations += result.iterations;
        evaluations += result.function_evaluations;
        time_s += result.time_s;
        solution = problem.full_configuration(result.x);
    }
    result.iterations = iterations;
    result.function_evaluations = evaluations;
    result.time_s = time_s;
    result.statistics["constraint_rounds"] = rounds;
    if (!problem.constraint_rows_suffice(solution)) {
        result.status = Status::failed;
        result.message = "after " + std::to_string(rounds) +
                         " solves a node outside the contact candidates is still inside a body (raise the margin)";
    }
    return result;
}

} // namespace sinew
