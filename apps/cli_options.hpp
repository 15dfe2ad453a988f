#pragma once
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace sinew::cli {

/// The solver flags shared by solve and bench, as the user typed them.
struct SolverFlags {
    SolverOptions options;
    std::vector<std::string> backend_options;  ///< "key=value" texts
};

/// --tol, --constr-tol, --kkt-tol, --max-iter, --option key=value (repeatable).
void add_solver_flags(CLI::App& command, SolverFlags& flags);

/// "key=value" split at the first '='; InputError naming `flag` when either
/// side is empty or there is no '='.
std::pair<std::string, std::string> split_key_value(const std::string& text, const std::string& flag);

/// InputError "<flag> = <value> is invalid; …" unless value > 0 (resp. ≥ 0)
/// and finite: for the flags CLI11 parses as doubles, which take "nan".
void require_positive_finite(double value, const std::string& flag);
void require_non_negative_finite(double value, const std::string& flag);

/// Options with the key=value texts parsed; InputError for a malformed one.
SolverOptions to_solver_options(const SolverFlags& flags);

/// A scene run request with what the user gave on `command`: --tol,
/// --max-iter and --load-steps set only when typed, so that the scene's own
/// settings hold otherwise; `options` as its base options.
SceneRunRequest scene_request(const CLI::App& command, const SolverOptions& options, int load_steps);

} // namespace sinew::cli
