#pragma once
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/contact_summary.hpp"
#include "sinew/runs/scene_run_settings.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// What a scene solve writes and how: the solver, its options, the number of
/// load steps, the output folder and which VTU files go into it.
struct SceneRunSettings {
    std::string solver;
    SolverOptions options;
    int load_steps = 1;
    std::string folder;  ///< created when missing; empty: nothing is written
    VtuOutput vtu = VtuOutput::final;
    VtuEncoding encoding = VtuEncoding::binary;
};

/// What the caller (the command line, a bench, a test) asks for beyond the
/// scene's own settings; unset fields leave the scene's.
struct SceneRunRequest {
    std::optional<std::string> solver;
    std::optional<double> tolerance;
    std::optional<int> max_iterations;
    std::optional<int> load_steps;
    std::string folder;     ///< empty: the scene's output folder (which may be empty too)
    SolverOptions options;  ///< the base options; its backend options win over the scene's
};

/// The settings a scene runs with, and one note for every setting of the
/// scene that the request overrides or that does not apply (DESIGN.md, "One
/// solve path": nothing is dropped silently).
struct ResolvedSceneRun {
    SceneRunSettings settings;
    std::vector<std::string> notes;
};

/// Precedence: the request, then the scene's settings, then defaults. The
/// scene's backend options go to the scene's solver only; a requested solver
/// that differs gets none of them, and a note lists them. InputError, naming
/// the scene's "solver" key, for invalid options of the scene's own solver.
ResolvedSceneRun resolve_scene_run(const Scene& scene, const SceneRunRequest& request);

/// Solves the scene in N load steps (s = k/N; each step starts from the
/// previous solution; Scene::apply_load_factor) and writes into the folder:
///
///   result.json   the scene, its settings, one summary per step, and the
///                 final solve's full result (status, x, history, …)
///   result.vtu    the final configuration (VtuOutput::final, every_step)
///   step_k.vtu    after load step k (VtuOutput::every_step)
///
/// Stops at the first step that does not converge and writes what it
/// reached. With an empty folder nothing is written. The one way a scene is
/// run: the CLI's solve and bench and the tests call it. A scene with
/// "dynamics" is stepped in time instead (run_time_stepping,
/// time_stepping.hpp): `last` is then the whole run as one result
/// (TimeSteppingOutcome::run), so comparisons and benches see every step.
/// A scene with "mpm" is run by run_mpm (mpm_run.hpp), `last` its run.
struct SceneRunOutcome {
    bool converged = false;  ///< every load step converged
    Result last;             ///< the last step's result
    int total_iterations = 0;
    double total_time_s = 0.0;
    /// Contact with the scene's bodies at the last solution (present only
    /// when the scene has bodies); result.json's "contact".
    ContactSummary contact;
};
SceneRunOutcome run_scene(Scene& scene, const SceneRunSettings& settings);

} // namespace sinew
