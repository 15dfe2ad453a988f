#pragma once
// The run settings a scene file carries: its "solver" and "output" parts,
// read by parts registered here (runs/, not problems/: how a scene is run is
// this layer's business) and kept in Scene::run_settings.
#include "sinew/mesh/vtu_writer.hpp"
#include "sinew/problems/quasistatic/scene.hpp"

#include <map>
#include <optional>
#include <string>

namespace sinew {

/// How a scene asks to be solved (its "solver" part). The runner turns this
/// into solver options (unset fields keep the solver's defaults or the
/// command line's values).
struct SceneSolverSettings {
    std::string name = "projected-newton";
    std::optional<double> tolerance;
    std::optional<int> max_iterations;
    std::map<std::string, std::string> options;  ///< backend options, as text
    std::string source;  ///< where these settings are written ("scene.json: solver"), for messages
};

/// Which VTU files a solve writes into the output folder.
enum class VtuOutput {
    none,        ///< result.json only
    final,       ///< result.vtu: the final configuration (default)
    every_step,  ///< also step_k.vtu after each load step (time step: every `every`-th)
};

/// Where a scene writes (its "output" part).
struct SceneOutput {
    std::string folder;  ///< resolved against the scene file's folder; empty: the CLI decides
    VtuOutput vtu = VtuOutput::final;
    int every = 1;  ///< time stepping with every_step: a VTU every this many steps
    VtuEncoding encoding = VtuEncoding::binary;  ///< "format": "binary" (default) or "ascii"
};

/// The scene's "solver" settings; defaults when it has none.
const SceneSolverSettings& scene_solver_settings(const Scene& scene);
/// The scene's "output" settings; defaults when it has none.
const SceneOutput& scene_output_settings(const Scene& scene);

} // namespace sinew
