#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace sinew::cli {

/// The solver flags shared by solve and bench, as the user typed them.
struct SolverFlags {
    SolverOptions options;
    std::vector<std::string> backend_options;  ///< "key=value" texts
};

/// --tol, --constr-tol, --kkt-tol, --max-iter, --option key=value (repeatable).
void add_solver_flags(CLI::App& command, SolverFlags& flags);

/// Options with the key=value texts parsed; InputError for a malformed one.
SolverOptions to_solver_options(const SolverFlags& flags);

} // namespace sinew::cli
