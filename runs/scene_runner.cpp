#include "sinew/runs/scene_runner.hpp"
#include "sinew/runs/refreshed_solve.hpp"

#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/scene_vtu.hpp"
#include "sinew/runs/time_stepping.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/constraint_ranks.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/solvers/solver.hpp"

#include <filesystem>

namespace sinew {
namespace {

nlohmann::json step_summary(int step, double load_factor, const Result& result)
{
    return {{"step", step},
            {"load_factor", load_factor},
            {"status", to_string(result.status)},
            {"iterations", result.iterations},
            {"objective", number(result.objective)},
            {"kkt_residual", number(result.kkt_residual)},
            {"time_s", number(result.time_s)}};
}

} // namespace

ResolvedSceneRun resolve_scene_run(const Scene& scene, const SceneRunRequest& request)
{
    ResolvedSceneRun resolved;
    SceneRunSettings& settings = resolved.settings;
    std::vector<std::string>& notes = resolved.notes;
    SolverOptions options = request.options;
    const SceneSolverSettings& solver = scene_solver_settings(scene);
    settings.solver = request.solver.value_or(solver.name);
    const std::string source = solver.source.empty() ? scene.name : solver.source;
    options.tolerance = request.tolerance.value_or(solver.tolerance.value_or(options.tolerance));
    if (request.tolerance && solver.tolerance)
        notes.push_back("tol " + format_number(*request.tolerance) + " overrides " + source + ".tol = " +
                        format_number(*solver.tolerance));
    options.max_iterations = request.max_iterations.value_or(solver.max_iterations.value_or(options.max_iterations));
    if (request.max_iterations && solver.max_iterations)
        notes.push_back("max_iter " + std::to_string(*request.max_iterations) + " overrides " + source +
                        ".max_iter = " + std::to_string(*solver.max_iterations));
    if (settings.solver == solver.name) {
        SolverOptions scene_options = options;
        scene_options.backend = solver.options;
        try {
            find_solver(solver.name).check_options(scene_options);
        } catch (const InputError& e) {
            throw InputError(source + ": " + e.what());
        }
        for (const auto& [key, value] : solver.options)
            if (!options.backend.emplace(key, value).second)
                notes.push_back("option " + key + "=" + options.backend.at(key) + " overrides " + source +
                                ".options." + key + " = " + value);
    } else {
        std::string ignored;
        for (const auto& [key, value] : solver.options)
            ignored += (ignored.empty() ? "" : ", ") + key + "=" + value;
        notes.push_back("solver " + settings.solver + " replaces the scene's " + solver.name +
                        (ignored.empty() ? "" : "; its options (" + ignored + ") are not passed to " + settings.solver));
    }
    settings.options = options;
    settings.load_steps = request.load_steps.value_or(scene.load_steps);
    if (request.load_steps && scene.load_steps != 1 && *request.load_steps != scene.load_steps)
        notes.push_back("load steps " + std::to_string(*request.load_steps) + " override the scene's " +
                        std::to_string(scene.load_steps));
    settings.folder = !request.folder.empty() ? request.folder : scene_output_settings(scene).folder;
    settings.vtu = scene_output_settings(scene).vtu;
    settings.encoding = scene_output_settings(scene).encoding;
    return resolved;
}

SceneRunOutcome run_scene(Scene& scene, const SceneRunSettings& settings)
{
    if (scene.mpm) {
        const MpmRunOutcome run = run_mpm(*scene.mpm, settings);
        return {run.converged, run.run, run.run.iterations, run.run.time_s, {}};
    }
    if (scene.dynamics) {
        const TimeSteppingOutcome stepped = run_time_stepping(scene, settings);
        return {stepped.converged, stepped.run, stepped.total_iterations, stepped.total_time_s, {}};
    }
    // Every input is checked before the output folder is made.
    check_solve(*scene.problem, settings.solver, settings.options);
    const bool writes = !settings.folder.empty();
    const std::string folder = settings.folder + "/";
    if (writes) {
        std::error_code error;
        std::filesystem::create_directories(settings.folder, error);
        if (error)
            throw InputError("cannot create output folder '" + settings.folder + "': " + error.message());
        check_writable(folder + "result.json");  // fail on an unwritable folder before the solve
    }

    QuasistaticProblem& problem = *scene.problem;
    nlohmann::json ranks = nlohmann::json::array();
    if (writes)
        for (const ConstraintSetRank& r : constraint_ranks(scene))
            ranks.push_back({{"constraints", r.set},
                             {"rows", r.rank.rows},
                             {"rank", r.rank.rank >= 0 ? nlohmann::json(r.rank.rank) : nlohmann::json()},
                             {"singular_value_ratio", number(r.rank.singular_value_ratio)}});
    nlohmann::json steps = nlohmann::json::array();
    nlohmann::json vtu_files = nlohmann::json::array();
    SceneRunOutcome outcome;
    Result& result = outcome.last;
    const int n = settings.load_steps;
    for (int k = 1; k <= n; ++k) {
        const double s = static_cast<double>(k) / n;
        scene.apply_load_factor(s);
        result = solve_with_refreshed_rows(problem, settings.solver, settings.options);
        outcome.total_time_s += result.time_s;
        outcome.total_iterations += result.iterations;
        steps.push_back(step_summary(k, s, result));
        const Eigen::VectorXd configuration = problem.full_configuration(result.x);
        if (writes && settings.vtu == VtuOutput::every_step && n > 1) {
            const std::string name = "step_" + std::to_string(k) + ".vtu";
            write_scene_vtu(folder + name, scene, configuration, result.constraint_multipliers, settings.encoding);
            vtu_files.push_back(name);
        }
        if (result.status != Status::converged || k == n) {
            if (writes && settings.vtu != VtuOutput::none) {
                write_scene_vtu(folder + "result.vtu", scene, configuration, result.constraint_multipliers,
                                settings.encoding);
                vtu_files.push_back("result.vtu");
            }
            break;
        }
        problem.set_starting_configuration(configuration);
    }
    outcome.converged = result.status == Status::converged && static_cast<int>(steps.size()) == n;
    const Eigen::VectorXd solution = problem.full_configuration(result.x);
    outcome.contact = contact_summary(scene_output_arrays(scene, solution, result.constraint_multipliers),
                                      Eigen::Map<const Eigen::MatrixXd>(solution.data(), scene.mesh.nodes.rows(),
                                                                        scene.mesh.num_nodes()));
    if (!writes)
        return outcome;
    nlohmann::json out = {{"scene", scene.name},
                                {"description", scene.description},
                                {"solver", settings.solver},
                                {"load_steps", n},
                                {"constraint_ranks", ranks},
                                {"converged", outcome.converged},
                                {"total_iterations", outcome.total_iterations},
                                {"total_time_s", outcome.total_time_s},
                                {"steps", steps},
                                {"vtu", vtu_files},
                                {"result", to_json(result)}};
    if (outcome.contact.present)
        out["contact"] = to_json(outcome.contact);
    write_text_file(folder + "result.json", out.dump(2) + "\n");
    return outcome;
}

} // namespace sinew
