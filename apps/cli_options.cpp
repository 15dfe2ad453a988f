#include "cli_options.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <cmath>

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

std::pair<std::string, std::string> split_key_value(const std::string& text, const std::string& flag)
{
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw InputError("malformed " + flag + " '" + text + "': expected key=value");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

void require_positive_finite(double value, const std::string& flag)
{
    if (!(value > 0.0 && std::isfinite(value)))
        throw InputError(flag + " = " + format_number(value) + " is invalid; it must be a positive finite number");
}

void require_non_negative_finite(double value, const std::string& flag)
{
    if (!(value >= 0.0 && std::isfinite(value)))
        throw InputError(flag + " = " + format_number(value) + " is invalid; it must be a finite number >= 0");
}

SolverOptions to_solver_options(const SolverFlags& flags)
{
    SolverOptions options = flags.options;
    for (const std::string& text : flags.backend_options) {
        const auto [key, value] = split_key_value(text, "--option");
        options.backend[key] = value;
    }
    validate(options);
    return options;
}

SceneRunRequest scene_request(const CLI::App& command, const SolverOptions& options, int load_steps)
{
    SceneRunRequest request;
    request.options = options;
    if (command.count("--tol") > 0)
        request.tolerance = options.tolerance;
    if (command.count("--max-iter") > 0)
        request.max_iterations = options.max_iterations;
    if (command.count("--load-steps") > 0)
        request.load_steps = load_steps;
    return request;
}

} // namespace sinew::cli
