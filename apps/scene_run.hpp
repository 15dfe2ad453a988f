#pragma once
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <string>

namespace sinew::cli {

/// What a scene solve writes and how: the solver, its options, the number of
/// load steps, the output folder and which VTU files go into it.
struct SceneRunSettings {
    std::string solver;
    SolverOptions options;
    int load_steps = 1;
    std::string folder;  ///< created when missing
    VtuOutput vtu = VtuOutput::final;
};

/// Solves the scene in N load steps (s = k/N; each step starts from the
/// previous solution; Scene::apply_load_factor) and writes into the folder:
///
///   result.json   the scene, its settings, one summary per step, and the
///                 final solve's full result (status, x, history, …)
///   result.vtu    the final configuration (VtuOutput::final, every_step)
///   step_k.vtu    after load step k (VtuOutput::every_step)
///
/// Stops at the first step that does not converge and writes what it
/// reached.
struct SceneRunOutcome {
    bool converged = false;  ///< every load step converged
    Result last;             ///< the last step's result
};
SceneRunOutcome run_scene(Scene& scene, const SceneRunSettings& settings);

} // namespace sinew::cli
