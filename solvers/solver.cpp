#include "sinew/solvers/solver.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/solvers/backends/ipopt_solver.hpp"
#include "sinew/solvers/backends/nlopt_solver.hpp"
#include "sinew/solvers/constrained/kkt_newton.hpp"
#include "sinew/solvers/constrained/penalty_method.hpp"
#include "sinew/solvers/constrained/relaxed_kkt.hpp"
#include "sinew/solvers/interior/interior_point.hpp"
#include "sinew/solvers/kkt_measures.hpp"
#include "sinew/solvers/newton/projected_newton.hpp"

#include <cstdio>
#include "sinew/solvers/progress_log.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace sinew {

void validate(const SolverOptions& options)
{
    auto positive = [](double value, const char* name) {
        if (!(value > 0.0) || !std::isfinite(value))
            throw InputError(std::string("solver option ") + name + " = " + format_number(value) +
                             " is invalid; it must be a positive finite number");
    };
    positive(options.tolerance, "tol");
    positive(options.constraint_tolerance, "constr_tol");
    positive(options.kkt_tolerance, "kkt_tol");
    if (options.max_iterations < 1)
        throw InputError("solver option max_iter = " + std::to_string(options.max_iterations) +
                         " is invalid; it must be at least 1");
    if (options.verbosity < 0 || options.verbosity > kMaxVerbosity)
        throw InputError("verbosity " + std::to_string(options.verbosity) + " is invalid; it must lie in [0, " +
                         std::to_string(kMaxVerbosity) + "]");
}

const std::vector<std::unique_ptr<Solver>>& all_solvers()
{
    static const std::vector<std::unique_ptr<Solver>> solvers = [] {
        std::vector<std::unique_ptr<Solver>> all;
        all.push_back(make_ipopt_solver());
        for (auto& s : make_nlopt_solvers())
            all.push_back(std::move(s));
        all.push_back(make_projected_newton_solver());
        all.push_back(make_kkt_newton_solver());
        all.push_back(make_interior_point_solver());
        all.push_back(make_relaxed_kkt_solver());
        all.push_back(make_penalty_solver());
        all.push_back(make_augmented_lagrangian_solver());
        return all;
    }();
    return solvers;
}

std::string option_text(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

bool takes_kappa(const Solver& solver) { return !solver.fixed_kappa_options(1.0).empty(); }

const Solver& find_solver(const std::string& name)
{
    std::string choices;
    for (const auto& s : all_solvers()) {
        if (s->name() == name)
            return *s;
        choices += (choices.empty() ? "" : ", ") + s->name();
    }
    throw InputError("unknown solver '" + name + "'; valid solvers: " + choices);
}

namespace {

/// Measures the result at its x the same way for every backend and decides
/// whether "converged" holds (SolverOptions says what that means).
void measure(Nlp& nlp, const SolverOptions& options, Result& result)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    result.objective = nlp.objective(result.x);
    result.constraint_violation = max_constraint_violation(nlp, result.x);
    if (!std::isfinite(result.objective) || !std::isfinite(result.constraint_violation)) {
        result.kkt_residual = kInfinity;
        if (result.status == Status::converged) {
            result.status = Status::numerical_error;
            result.message += "; objective or constraints not finite at the returned x";
        }
        return;
    }
    const bool has_multipliers = result.constraint_multipliers.size() == m &&
                                 result.bound_multipliers_lower.size() == n &&
                                 result.bound_multipliers_upper.size() == n;
    if (!has_multipliers) {
        estimate_multipliers(nlp, result.x, std::sqrt(options.constraint_tolerance), result.constraint_multipliers,
                             result.bound_multipliers_lower, result.bound_multipliers_upper);
        result.multipliers_estimated = true;
    }
    result.kkt_residual = kkt_residual(nlp, result.x, result.constraint_multipliers, result.bound_multipliers_lower,
                                       result.bound_multipliers_upper);
    if (result.status != Status::converged)
        return;

    Eigen::VectorXd gradient(n);
    nlp.gradient(result.x, gradient);
    const double kkt_bound = options.kkt_tolerance * std::max(1.0, gradient.cwiseAbs().maxCoeff());
    std::ostringstream why;
    if (result.constraint_violation > options.constraint_tolerance)
        why << "constraint violation " << result.constraint_violation << " > constr_tol "
            << options.constraint_tolerance;
    else if (!(result.kkt_residual <= kkt_bound))
        why << "KKT residual " << result.kkt_residual << " > kkt_tol · max(1, |grad f|) = " << kkt_bound;
    if (why.str().empty())
        return;
    // Close to a solution the backend's success test and ours may disagree a
    // little; a "success" far from one (an early stop while infeasible, a
    // divergence) is a failure, whatever the backend called it.
    const bool far = result.constraint_violation > kFarFromTolerance * options.constraint_tolerance ||
                     !(result.kkt_residual <= kFarFromTolerance * kkt_bound);
    result.status = far ? Status::failed : Status::tolerance_not_met;
    result.message += (result.message.empty() ? "" : "; but ") + why.str() +
                      (far ? ", more than " + format_number(kFarFromTolerance) + " times the tolerance" : "");
}

} // namespace

void check_solve(const Nlp& nlp, const std::string& solver_name, const SolverOptions& options)
{
    validate(options);
    const Solver& solver = find_solver(solver_name);
    solver.check_options(options);
    if (const auto why = solver.refusal(nlp))
        throw InputError("solver " + solver.name() + " cannot solve " + nlp.name() + " (" + capabilities_of(nlp).describe() +
                         "): " + *why);
}

Result solve(Nlp& nlp, const std::string& solver_name, const SolverOptions& options)
{
    check_solve(nlp, solver_name, options);
    const Solver& solver = find_solver(solver_name);
    const auto start = std::chrono::steady_clock::now();
    Result result = solver.run(nlp, options);
    result.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.solver = solver.name();
    result.problem = nlp.name();
    measure(nlp, options, result);
    log_summary(options, result);
    return result;
}

} // namespace sinew
