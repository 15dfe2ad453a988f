#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sinew::cli {

/// Suite strategies of `sinew bench`: a comparison (`sinew compare`, default
/// κ; every solver that accepts the problem, or those of `solvers`) on every built-in scene of suite inextensibility and
/// every Hock-Schittkowski problem of suite constrained (or only `problems`),
/// each written to `<folder>/<problem>/` and printed as a markdown table,
/// then Dolan-Moré profiles of iterations and time across all of them
/// (solved: converged) as tables and as plots in `folder`. The relaxed
/// strategies enter the profiles by their place in the κ sweep (κ₁ < κ₂ <
/// κ₃), since each problem has its own κ. Every run goes into `runs`. True
/// when every comparison has a converged reference.
bool run_strategies_bench(const std::string& folder, const std::vector<std::string>& solvers,
                          const std::vector<std::string>& problems, const SolverOptions& options, bool plots,
                          nlohmann::json& runs);

} // namespace sinew::cli
