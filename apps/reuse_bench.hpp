#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sinew::cli {

/// Suite reuse of `sinew bench` (issue 14): every built-in scene (or only
/// those named in `scenes`) solved by the shared Newton core twice, with
/// reuse_factorization off and on: the scenes projected Newton solves by
/// projected-newton, the constrained ones by augmented-lagrangian (its
/// subproblems are the core's; kkt-newton factorizes an indefinite KKT
/// matrix and does not reuse). Prints one markdown table: status,
/// iterations, factorizations, CG iterations, the factorization, CG and total
/// times, the time ratio on/off, and how far the two solutions lie apart
/// (max |x_on − x_off| / max |x_off − x₀|). Every run goes into `runs`.
/// True when every run converged.
bool run_reuse_bench(const std::vector<std::string>& scenes, const SolverOptions& options, nlohmann::json& runs);

} // namespace sinew::cli
