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
#include <cmath>
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
    int rig_tets = 20000;
    double rig_noise_mm = 0.0;
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

constexpr const char* kFaceRig = "face-rig";

/// The subject: a scene file, the face rig, or a built-in scene or problem by name.
ComparisonSubject make_subject(const CompareFlags& flags, const CLI::App& command, const SceneRunRequest& request)
{
    const bool rig_flags = command.count("--rig-tets") > 0 || command.count("--rig-noise") > 0;
    if (flags.problem == kFaceRig) {
        if (request.load_steps)
            throw InputError("--load-steps applies to scenes only ('face-rig' is not one)");
        if (!std::isfinite(flags.rig_noise_mm) || flags.rig_noise_mm < 0.0)
            throw InputError("--rig-noise: the noise must be finite and >= 0 (mm), not " +
                             format_number(flags.rig_noise_mm));
        return rig_subject(kFaceRig, face_fit_case(flags.rig_tets, 1e-3 * flags.rig_noise_mm));
    }
    if (rig_flags)
        throw InputError("--rig-tets and --rig-noise apply to face-rig only");
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
    std::vector<ComparedStrategy> strategies = comparison_strategies(*nlp, flags.solvers, kappas, refusals);
    for (const ComparedStrategy& variant : subject.variants)
        if (flags.solvers.empty() ||
            std::find(flags.solvers.begin(), flags.solvers.end(), variant.solver) != flags.solvers.end())
            strategies.push_back(variant);
    // A solver that refuses the subject's NLP but runs one of its variants is not left out.
    refusals.erase(std::remove_if(refusals.begin(), refusals.end(),
                                  [&](const std::string& why) {
                                      const std::string solver = why.substr(0, why.find(':'));
                                      return std::any_of(strategies.begin(), strategies.end(),
                                                         [&](const ComparedStrategy& s) { return s.solver == solver; });
                                  }),
                   refusals.end());
    if (!flags.solvers.empty() && !refusals.empty())
        throw InputError("--solvers: " + refusals.front());
    if (strategies.empty())
        throw InputError("no solver accepts '" + subject.name + "'");
    for (const ComparedStrategy& strategy : strategies)
        if (strategy.form.empty())  // a variant poses another NLP, which its run checks
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
    command->add_option("problem", flags->problem,
                        "a scene file *.json, a built-in problem (see sinew list), or face-rig (fitting the face "
                        "rig to synthesized landmarks: the constrained fit by every solver that takes it and by "
                        "ipopt with the Gauss-Newton Hessian, the seed's penalty form and rotation vectors by "
                        "projected-newton)")
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
    command->add_option("--rig-tets", flags->rig_tets, "face-rig: the face's size, tets aimed at (default 20000)")
        ->check(CLI::Range(1000, 2000000));
    command->add_option("--rig-noise", flags->rig_noise_mm,
                        "face-rig: standard deviation of the Gaussian landmark noise, mm (default 0)");
    command->add_flag("--quiet", flags->quiet, "no progress on standard error");
    command->add_flag("--no-plots", flags->no_plots, "write the table and compare.json only");
    add_solver_flags(*command, flags->solver_flags);

    command->callback([flags, command, &exit_code] {
        const SolverOptions options = to_solver_options(flags->solver_flags);
        check_kappas(flags->kappas);
        const ComparisonSubject subject = make_subject(*flags, *command, scene_request(*command, options, flags->load_steps));
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
