#include "cli_options.hpp"
#include "commands.hpp"
#include "comparison_progress.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/comparison_report.hpp"
#include "sinew/runs/comparison_subjects.hpp"
#include "sinew/runs/gnuplot_plot.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/solvers/solver.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>

namespace sinew::cli {
namespace {

struct CompareFlags {
    std::string problem;
    std::vector<std::string> solvers;
    std::vector<double> kappas;  ///< empty: default_kappas()
    std::string output;
    int load_steps = 1;
    bool quiet = false;
    bool no_plots = false;
    SolverFlags solver_flags;
};

void check_kappas(const std::vector<double>& kappas)
{
    for (size_t i = 0; i < kappas.size(); ++i) {
        require_positive_finite(kappas[i], "--kappa");
        for (size_t j = 0; j < i; ++j)
            if (kappas[j] == kappas[i])
                throw InputError("--kappa: " + format_number(kappas[i]) + " is listed twice");
    }
}

/// The subject: a scene file, or a built-in scene or problem by name.
ComparisonSubject make_subject(const CompareFlags& flags, const SceneRunRequest& request)
{
    if (std::filesystem::path(flags.problem).extension() == ".json") {
        const std::string path = flags.problem;
        return scene_subject([path] { return read_scene_file(path); }, request);
    }
    const BuiltinProblem& problem = find_builtin_problem(flags.problem);
    if (problem.scene.empty() && request.load_steps)
        throw InputError("--load-steps applies to scenes only ('" + flags.problem + "' is not one)");
    return builtin_subject(problem, request);
}

/// The strategies to run; InputError when a solver the user named refuses
/// the problem or none is left. `refusals`: the solvers left out, and why.
std::vector<ComparedStrategy> chosen_strategies(const CompareFlags& flags, const ComparisonSubject& subject,
                                                const SolverOptions& options, std::vector<std::string>& refusals)
{
    for (const auto& name : flags.solvers)
        find_solver(name);
    const std::unique_ptr<Nlp> nlp = subject.make_nlp();
    const std::vector<double> kappas = flags.kappas.empty() ? default_kappas(*nlp) : flags.kappas;
    const std::vector<ComparedStrategy> strategies = comparison_strategies(*nlp, flags.solvers, kappas, refusals);
    if (!flags.solvers.empty() && !refusals.empty())
        throw InputError("--solvers: " + refusals.front());
    if (strategies.empty())
        throw InputError("no solver accepts '" + subject.name + "'");
    for (const ComparedStrategy& strategy : strategies)
        check_solve(*nlp, strategy.solver, strategy_options(strategy, options));
    return strategies;
}

} // namespace

void add_compare_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "compare", "run several strategies on one scene or problem and write a markdown table (compare.md), every "
                   "run's result (compare.json) and convergence plots (PNG, SVG, by gnuplot) into a folder; exit 0 "
                   "when at least one strategy converged, 3 when none did (the files are written either way)");
    auto flags = std::make_shared<CompareFlags>();
    command->add_option("problem", flags->problem, "a scene file *.json or a built-in problem (see sinew list)")
        ->required();
    command->add_option("--solvers", flags->solvers,
                        "comma-separated solvers (default: every solver that accepts the problem)")
        ->delimiter(',');
    command->add_option("--kappa", flags->kappas,
                        "comma-separated stiffnesses for relaxed-kkt and penalty (default: 10, 1e3 and 1e5 times the "
                        "problem's kappa scale, max diag of the Hessian over max diag of J^T J, in powers of ten)")
        ->delimiter(',');
    command->add_option("--output", flags->output, "folder for the files (default: <name>-compare)");
    command->add_option("--load-steps", flags->load_steps, "scenes: equal load steps (default: the scene's)")
        ->check(CLI::Range(1, std::numeric_limits<int>::max()));
    command->add_flag("--quiet", flags->quiet, "no progress on standard error");
    command->add_flag("--no-plots", flags->no_plots, "write the table and compare.json only");
    add_solver_flags(*command, flags->solver_flags);

    command->callback([flags, command, &exit_code] {
        const SolverOptions options = to_solver_options(flags->solver_flags);
        check_kappas(flags->kappas);
        const ComparisonSubject subject = make_subject(*flags, scene_request(*command, options, flags->load_steps));
        std::vector<std::string> refusals;
        const std::vector<ComparedStrategy> strategies = chosen_strategies(*flags, subject, options, refusals);
        if (!flags->no_plots && !gnuplot_available())
            throw InputError(gnuplot_missing_message());
        const std::string folder = flags->output.empty() ? subject.name + "-compare" : flags->output;
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error)
            throw InputError("cannot create output folder '" + folder + "': " + error.message());
        check_writable(folder + "/compare.json");  // an unwritable folder fails before the runs

        std::ostream* log = flags->quiet ? nullptr : &std::cerr;
        if (log)
            for (const auto& why : refusals)
                *log << "sinew compare: left out " << why << "\n";
        const Comparison comparison = run_comparison(
            subject, strategies, options, log ? comparison_progress(*log, subject.name) : ComparisonProgress{});
        write_comparison(comparison, folder, !flags->no_plots);
        std::cout << comparison_markdown(comparison);
        const bool any_converged =
            std::any_of(comparison.runs.begin(), comparison.runs.end(),
                        [](const ComparisonRun& run) { return run.result.status == Status::converged; });
        exit_code = any_converged ? 0 : 3;
    });
}

} // namespace sinew::cli
