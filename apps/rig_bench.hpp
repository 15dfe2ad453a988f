#pragma once
#include "sinew/solvers/solver_options.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sinew::cli {

/// Suite rig of `sinew bench` (issue 15): for each face size (`sizes`, tets
/// aimed at), targets synthesized from a known θ* (synthesize_targets), once
/// exact and once with 1 mm noise (seed 1), fitted from the neutral rig by
/// every strategy of rig_fit_strategies (or those whose solver or label
/// `solvers` names); one markdown table per size and noise, and a table of what one
/// outer iteration costs at θ* (equilibrium solve, factorization, forward
/// sensitivities for every parameter, adjoint gradient). `options`: the
/// outer solves' tolerance and limits; `skull_contact`: the faces pressed
/// against their skulls (face_rig), the tables adding the deepest node and
/// the skull's force. Each fit row ends with its branch check
/// (RigFitOutcome::branch_distance). Every run goes into `runs`. True when
/// every fit converged.
/// Everything run_rig_bench checks before it generates a face: InputError
/// unless each name is the solver or the label of a strategy of
/// rig_fit_strategies (naming the valid ones), or when a chosen strategy's
/// solver refuses its options (`options` with the strategy's own).
void check_rig_strategies(const std::vector<std::string>& names, const SolverOptions& options);

bool run_rig_bench(const std::vector<int>& sizes, const std::vector<std::string>& solvers,
                   const SolverOptions& options, bool skull_contact, nlohmann::json& runs);

} // namespace sinew::cli
