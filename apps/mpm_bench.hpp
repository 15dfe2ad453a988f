#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

namespace sinew::cli {

/// Suite mpm of `sinew bench` (issue 33; docs/benchmarks.md):
///   explicit steps of a 3D block of 10⁴, 10⁵ and 10⁶ particles (quadratic
///   B-splines, APIC, fixed corotated) on each thread count up to the
///   machine's cores: particle-steps per second and the share of time in
///   P2G, the stress divergence, the grid update and G2P (with advection),
///   beside the bytes a particle-step moves and the machine's measured
///   memory bandwidth;
///   implicit steps of the scenes in scenes/mpm/ at ten times their explicit
///   CFL bound with the scene's solver: Newton iterations and time per step,
///   and the wall time per simulated second against explicit steps at the bound.
/// Prints markdown tables; every run goes into `runs`. True when every run
/// converged.
bool run_mpm_bench(const SolverOptions& options, nlohmann::json& runs);

} // namespace sinew::cli
