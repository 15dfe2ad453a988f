#include "dynamics_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/time_stepping.hpp"
#include "sinew/time/time_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace sinew::cli {
namespace {

/// What one run of the table measured.
struct DynamicsRun {
    std::string scene, integrator, solver;
    TimeSteppingOutcome outcome;
    double factorizations = -1.0;  ///< total; −1 when the solver does not count them
    double drift = 0.0;
    double violation = 0.0;
};

DynamicsRun run_one(const std::string& name, const std::string& integrator, const std::optional<std::string>& solver,
                    const SolverOptions& options)
{
    Scene scene = make_builtin_scene(name);
    scene.dynamics->integrator = integrator;
    SceneRunRequest request;
    request.solver = solver;
    request.options = options;
    const SceneRunSettings settings = resolve_scene_run(scene, request).settings;
    DynamicsRun run{name, integrator, settings.solver, run_time_stepping(scene, settings)};
    const std::vector<TimeStepRow>& steps = run.outcome.steps;
    double largest_kinetic = 0.0;
    for (const TimeStepRow& row : steps) {
        largest_kinetic = std::max(largest_kinetic, row.kinetic_energy);
        run.violation = std::max(run.violation, row.max_constraint_violation);
        if (row.factorizations >= 0)
            run.factorizations = std::max(0.0, run.factorizations) + row.factorizations;
    }
    run.drift = largest_kinetic > 0.0
                    ? (steps.back().total_energy - steps.front().total_energy) / largest_kinetic
                    : std::nan("");
    return run;
}

std::string row(const DynamicsRun& run)
{
    const int steps = static_cast<int>(run.outcome.steps.size()) - 1;
    const double per_step = steps > 0 ? 1.0 / steps : 0.0;
    return "| " + run.scene + " | " + run.integrator + " | " + run.solver + " | " +
           (run.outcome.converged ? "converged" : to_string(run.outcome.last.status)) + " | " +
           std::to_string(steps) + " | " + table_cell("%.2f", run.outcome.total_iterations * per_step) + " | " +
           (run.factorizations >= 0 ? table_cell("%.2f", run.factorizations * per_step) : "-") + " | " +
           table_cell("%.1f", 1e3 * run.outcome.total_time_s * per_step) + " | " + table_cell("%.2e", run.drift) +
           " | " + table_cell("%.1e", run.violation) + " |";
}

} // namespace

bool run_dynamics_bench(const std::vector<std::string>& scenes, const std::optional<std::string>& solver,
                        const SolverOptions& options, nlohmann::json& runs)
{
    std::cout << "| scene | integrator | solver | status | steps | iterations / step | factorizations / step "
                 "| time / step (ms) | energy drift | max \\|c\\| |\n"
              << "|---|---|---|---|---:|---:|---:|---:|---:|---:|\n";
    bool all_converged = true;
    for (const BuiltinSceneFile& file : builtin_scene_files()) {
        if (!file.dynamic || (!scenes.empty() && std::find(scenes.begin(), scenes.end(), file.name) == scenes.end()))
            continue;
        for (const std::string& integrator : integrator_names()) {
            const DynamicsRun run = run_one(file.name, integrator, solver, options);
            std::cout << row(run) << std::endl;
            nlohmann::json entry = to_json(run.outcome.last);
            entry["scene"] = run.scene;
            entry["integrator"] = run.integrator;
            entry["steps"] = static_cast<int>(run.outcome.steps.size()) - 1;
            entry["converged_run"] = run.outcome.converged;
            entry["total_iterations"] = run.outcome.total_iterations;
            entry["total_time_s"] = run.outcome.total_time_s;
            entry["energy_drift"] = number(run.drift);
            runs.push_back(entry);
            all_converged = all_converged && run.outcome.converged;
        }
    }
    return all_converged;
}

} // namespace sinew::cli
