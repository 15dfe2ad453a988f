#include "cli_options.hpp"

#include "sinew/core/input_error.hpp"

namespace sinew::cli {

void add_solver_flags(CLI::App& command, SolverFlags& flags)
{
    SolverOptions& o = flags.options;
    command.add_option("--tol", o.tolerance, "backend stopping tolerance (Ipopt tol, NLopt ftol_rel/xtol_rel)")
        ->capture_default_str();
    command.add_option("--constr-tol", o.constraint_tolerance, "largest constraint violation accepted as feasible")
        ->capture_default_str();
    command.add_option("--kkt-tol", o.kkt_tolerance, "largest KKT residual, relative to max(1, |grad f|), accepted as optimal")
        ->capture_default_str();
    command.add_option("--max-iter", o.max_iterations, "iteration limit (NLopt: evaluation limit)")->capture_default_str();
    command.add_option("--option", flags.backend_options,
                       "backend option key=value, repeatable (any Ipopt option by name; NLopt: ftol_rel, ftol_abs, "
                       "xtol_rel, xtol_abs, maxtime, vector_storage)");
}

SolverOptions to_solver_options(const SolverFlags& flags)
{
    SolverOptions options = flags.options;
    for (const std::string& text : flags.backend_options) {
        const auto eq = text.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
            throw InputError("malformed --option '" + text + "': expected key=value");
        options.backend[text.substr(0, eq)] = text.substr(eq + 1);
    }
    validate(options);
    return options;
}

} // namespace sinew::cli
