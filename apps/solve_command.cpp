#include "cli_options.hpp"
#include "commands.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/runs/time_stepping.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/problems/quasistatic/constraint_ranks.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/solvers/solver.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>

namespace sinew::cli {
namespace {

bool is_scene_file(const std::string& problem)
{
    return std::filesystem::path(problem).extension() == ".json";
}

std::atomic<bool> interrupt_requested{false};

extern "C" void request_interrupt(int) { interrupt_requested = true; }

/// Runs a scene stepped in time with one progress line per step on stderr
/// (verbosity >= 1; the steps' own iteration tables from verbosity 2), and
/// Ctrl-C ending the run after the current step with its output written.
TimeSteppingOutcome run_time_stepping_with_progress(Scene& scene, SceneRunSettings settings)
{
    const int verbosity = settings.options.verbosity;
    settings.options.verbosity = verbosity > 0 ? verbosity - 1 : 0;
    const long long planned = scene.dynamics->num_steps();
    TimeSteppingObserver observer;
    if (verbosity > 0)
        observer.on_step = [planned](const TimeStepRow& row, const TimeState&) {
            if (row.step > 0)
                std::fprintf(stderr, "sinew: step %d of %lld  t = %.6g s  %s in %d iterations  E = %.9g\n", row.step,
                             planned, row.time, to_string(row.status).c_str(), row.iterations, row.total_energy);
        };
    observer.stop_requested = [] { return interrupt_requested.load(); };
    interrupt_requested = false;
    const auto previous = std::signal(SIGINT, request_interrupt);
    try {
        TimeSteppingOutcome outcome = run_time_stepping(scene, settings, observer);
        std::signal(SIGINT, previous);
        return outcome;
    } catch (...) {
        std::signal(SIGINT, previous);
        throw;
    }
}

/// Runs an MPM scene with one progress line per frame on stderr (verbosity >= 1).
MpmRunOutcome run_mpm_with_progress(const MpmScene& scene, const SceneRunSettings& settings)
{
    std::function<void(const MpmFrameRow&)> on_frame;
    if (settings.options.verbosity > 0)
        on_frame = [&scene](const MpmFrameRow& row) {
            if (row.frame > 0)
                std::fprintf(stderr, "sinew: frame %d of %d  t = %.6g s  %lld steps  E = %.9g  J in [%.4g, %.4g]\n",
                             row.frame, scene.frames, row.time, row.steps, row.total_energy, row.min_J, row.max_J);
        };
    return run_mpm(scene, settings, on_frame);
}

} // namespace

void add_solve_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "solve", "solve a built-in problem or a scene file (scene.json) with one solver; exit 0 when converged, "
                 "3 when not (the result is written either way)");
    struct Flags {
        std::string problem;
        std::string solver = "ipopt";
        std::string json;
        std::string output;
        int load_steps = 1;
        int verbosity = 1;
        SolverFlags solver_flags;
    };
    auto flags = std::make_shared<Flags>();
    command->add_option("problem", flags->problem, "built-in problem name (see sinew list) or a scene file *.json")
        ->required();
    command->add_option("--solver", flags->solver,
                        "solver name (see sinew list); default: the scene's solver, ipopt for other problems");
    command->add_option("--json", flags->json, "write the result (status, x, multipliers, history, ...) to this file");
    command->add_option("--output", flags->output,
                        "scenes: folder for result.json and VTU files (default: the scene's output.folder, else "
                        "<scene name>-output for a scene file; a built-in scene writes only with --output)");
    command->add_option("--load-steps", flags->load_steps, "scenes: number of equal load steps (default: the scene's)")
        ->check(CLI::Range(1, std::numeric_limits<int>::max()));
    command->add_option("--verbosity", flags->verbosity, "0 silent, 1 iteration table, 2 backend output")
        ->capture_default_str()
        ->check(CLI::Range(0, kMaxVerbosity));
    add_solver_flags(*command, flags->solver_flags);

    command->callback([flags, command, &exit_code] {
        SolverOptions options = to_solver_options(flags->solver_flags);
        options.verbosity = flags->verbosity;
        if (!flags->json.empty())
            check_writable(flags->json);  // fail on a bad path before the solve, not after
        const bool scene_file = is_scene_file(flags->problem);
        const BuiltinProblem* builtin = scene_file ? nullptr : &find_builtin_problem(flags->problem);
        const bool is_scene = scene_file || !builtin->scene.empty();
        if (!is_scene) {
            if (command->count("--load-steps") > 0)
                throw InputError("--load-steps applies to scenes only ('" + flags->problem + "' is not one)");
            const std::unique_ptr<Nlp> nlp = builtin->make();
            const Result result = solve(*nlp, flags->solver, options);
            if (!flags->json.empty())
                write_text_file(flags->json, to_json(result).dump(2) + "\n");
            exit_code = result.status == Status::converged ? 0 : 3;
            return;
        }

        Scene scene = scene_file ? read_scene_file(flags->problem) : make_builtin_scene(builtin->scene);
        SceneRunRequest request = scene_request(*command, options, flags->load_steps);
        if (command->count("--solver") > 0)
            request.solver = flags->solver;
        // A scene file writes into its output folder (default <name>-output);
        // a built-in scene only where --output says.
        request.folder = !flags->output.empty() || !scene_file || !scene_output_settings(scene).folder.empty()
                             ? flags->output
                             : scene.name + "-output";
        const ResolvedSceneRun run = resolve_scene_run(scene, request);
        if (scene.mpm) {
            const MpmRunOutcome outcome = run_mpm_with_progress(*scene.mpm, run.settings);
            if (!flags->json.empty())
                write_text_file(flags->json, to_json(outcome.run).dump(2) + "\n");
            exit_code = outcome.converged ? 0 : 3;
            return;
        }
        check_solve(*scene.problem, run.settings.solver, run.settings.options);
        for (const std::string& note : run.notes)
            std::cerr << "sinew: note: " << note << "\n";
        for (const ConstraintSetRank& rank : constraint_ranks(scene))
            std::cerr << "sinew: note: " << describe(rank) << "\n";
        if (scene.dynamics) {
            const TimeSteppingOutcome stepped = run_time_stepping_with_progress(scene, run.settings);
            if (!flags->json.empty())
                write_text_file(flags->json, to_json(stepped.last).dump(2) + "\n");
            exit_code = stepped.converged ? 0 : 3;
            return;
        }
        const SceneRunOutcome outcome = run_scene(scene, run.settings);
        if (!flags->json.empty())
            write_text_file(flags->json, to_json(outcome.last).dump(2) + "\n");
        exit_code = outcome.converged ? 0 : 3;
    });
}

} // namespace sinew::cli
