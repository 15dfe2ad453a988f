#include "sinew/inverse/equilibrium_solve.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/solver.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

constexpr const char* kInnerSolver = "projected-newton";

/// ‖∇_U E‖∞ at the variables x.
double gradient_norm(QuasistaticProblem& problem, const Eigen::VectorXd& x)
{
    Eigen::VectorXd gradient(problem.num_variables());
    problem.gradient(x, gradient);
    return gradient.cwiseAbs().maxCoeff();
}

} // namespace

EquilibriumSolve solve_equilibrium(QuasistaticProblem& problem, const EquilibriumSolveSettings& settings)
{
    const double cold = gradient_norm(problem, problem.variables_of(problem.prescribed_configuration()));
    const double given = gradient_norm(problem, problem.starting_point());
    const double scale = std::max({std::isfinite(cold) ? cold : 0.0, given, settings.force_scale});
    SolverOptions options = settings.options;
    if (scale > 0.0 && options.backend.count("gradient_target") == 0) {  // unless the caller set it
        const double target = options.tolerance * scale;
        options.backend["gradient_target"] = format_number(target);
        // solve() checks ‖∇_U E‖∞ ≤ kkt_tol · max(1, ‖∇_U E‖∞) afterwards: the
        // same quantity, so it must not ask for less than the target does.
        options.kkt_tolerance = std::max(options.kkt_tolerance, target);
    }
    EquilibriumSolve outcome;
    outcome.result = solve(problem, kInnerSolver, options);
    outcome.converged = outcome.result.status == Status::converged;
    if (outcome.converged)
        outcome.configuration = problem.full_configuration(outcome.result.x);
    else
        outcome.failure = std::string("the equilibrium solve (") + kInnerSolver + ") stopped with " +
                          to_string(outcome.result.status) + " after " +
                          std::to_string(outcome.result.iterations) + " iterations, KKT residual " +
                          format_number(outcome.result.kkt_residual);
    return outcome;
}

} // namespace sinew
