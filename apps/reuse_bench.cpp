#include "reuse_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/scene_runner.hpp"

#include <algorithm>
#include <iostream>

namespace sinew::cli {
namespace {

/// The solver of the Newton core for a scene: its own when that is projected
/// Newton, else augmented Lagrangian, whose subproblems projected Newton solves.
std::string core_solver(const Scene& scene)
{
    return scene_solver_settings(scene).name == "projected-newton" ? "projected-newton" : "augmented-lagrangian";
}

/// The backend option that switches reuse for `solver` (nested for the outer loops).
std::string reuse_key(const std::string& solver)
{
    return solver == "projected-newton" ? "reuse_factorization" : "inner.reuse_factorization";
}

struct ReuseRun {
    Result result;
    Eigen::VectorXd start;
};

ReuseRun run_with_reuse(const std::string& name, const std::string& solver, const std::string& reuse,
                        const SolverOptions& options)
{
    Scene scene = make_builtin_scene(name);
    ReuseRun run;
    run.start = scene.problem->starting_point();
    SceneRunRequest request;
    request.solver = solver;
    request.options = options;
    request.options.backend[reuse_key(solver)] = reuse;
    run.result = run_scene(scene, resolve_scene_run(scene, request).settings).last;
    return run;
}

double statistic(const Result& result, const std::string& name)
{
    const auto found = result.statistics.find(name);
    return found == result.statistics.end() ? 0.0 : found->second;
}

/// max |x_on − x_off| / max |x_off − x₀|.
double relative_distance(const ReuseRun& off, const ReuseRun& on)
{
    if (off.result.x.size() != on.result.x.size() || off.result.x.size() == 0)
        return kInfinity;
    const double displacement = (off.result.x - off.start).cwiseAbs().maxCoeff();
    return (on.result.x - off.result.x).cwiseAbs().maxCoeff() / std::max(displacement, 1e-300);
}

std::string row(const std::string& scene, const std::string& solver, const std::string& reuse, const Result& r,
                const std::string& ratio, const std::string& distance)
{
    return "| " + scene + " | " + solver + " | " + reuse + " | " + to_string(r.status) + " | " +
           std::to_string(r.iterations) + " | " + table_cell("%.0f", statistic(r, "factorizations")) + " | " +
           table_cell("%.0f", statistic(r, "cg_iterations")) + " | " + table_cell("%.3f", statistic(r, "factorization_s")) +
           " | " + table_cell("%.3f", statistic(r, "cg_s")) + " | " + table_cell("%.3f", r.time_s) + " | " + ratio +
           " | " + distance + " |";
}

} // namespace

bool run_reuse_bench(const std::vector<std::string>& scenes, const SolverOptions& options, nlohmann::json& runs)
{
    std::cout << "| scene | solver | reuse | status | iterations | factorizations | CG iterations "
                 "| factorization (s) | CG (s) | total (s) | on / off | solutions apart |\n"
              << "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    bool all_converged = true;
    for (const BuiltinSceneFile& file : builtin_scene_files()) {
        if (file.dynamic)
            continue;  // the dynamics suite measures time stepping
        if (!scenes.empty() && std::find(scenes.begin(), scenes.end(), file.name) == scenes.end())
            continue;
        const std::string solver = core_solver(make_builtin_scene(file.name));
        const ReuseRun off = run_with_reuse(file.name, solver, "off", options);
        std::cout << row(file.name, solver, "off", off.result, "", "") << std::endl;
        const ReuseRun on = run_with_reuse(file.name, solver, "on", options);
        std::cout << row(file.name, solver, "on", on.result, table_cell("%.2f", on.result.time_s / off.result.time_s),
                         table_cell("%.1e", relative_distance(off, on)))
                  << std::endl;
        for (const auto* run : {&off, &on}) {
            nlohmann::json entry = to_json(run->result);
            entry["scene"] = file.name;
            entry["reuse_factorization"] = run == &off ? "off" : "on";
            runs.push_back(entry);
            all_converged = all_converged && run->result.status == Status::converged;
        }
    }
    return all_converged;
}

} // namespace sinew::cli
