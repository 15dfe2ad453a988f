#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sinew::cli {

/// Suite dynamics of `sinew bench` (issue 31): every scene of scenes/dynamics/
/// (or only those named in `scenes`) stepped in time under each integrator,
/// with the scene's solver (or `solver`). Prints one markdown table: steps,
/// status, Newton iterations and factorizations per step, time per step,
/// the energy drift (E_N − E_0) / max_n KE_n (E = kinetic + elastic − the
/// work of gravity and loads; meaningful where nothing drives the motion)
/// and the largest constraint violation over the run. Every run goes into
/// `runs`. True when every run converged.
bool run_dynamics_bench(const std::vector<std::string>& scenes, const std::optional<std::string>& solver,
                        const SolverOptions& options, nlohmann::json& runs);

} // namespace sinew::cli
