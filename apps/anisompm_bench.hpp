#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

namespace sinew::cli {

/// Suite anisompm of `sinew bench` (issue 34; docs/benchmarks.md): every
/// scene of scenes/anisompm/ run as its file says (no output written):
/// particles, frames, steps, and the wall time per frame split into the
/// transfers, the damage update and the momentum update; the damage
/// solves' CG iterations per step, how often the bounds of d acted, and the
/// damage at the end. Scenes differing only in their damage update sit in
/// adjacent rows (explicit against implicit). Prints one markdown table;
/// every run goes into `runs`. True when every run reached its duration.
bool run_anisompm_bench(const SolverOptions& options, nlohmann::json& runs);

} // namespace sinew::cli
