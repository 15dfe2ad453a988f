#include "cli_options.hpp"
#include "commands.hpp"
#include "anisompm_bench.hpp"
#include "dynamics_bench.hpp"
#include "mpm_bench.hpp"
#include "reuse_bench.hpp"
#include "rig_bench.hpp"
#include "strategies_bench.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"

#include "sinew/bench/kernel_benchmark.hpp"
#include "sinew/bench/performance_profile.hpp"
#include "sinew/bench/reference_check.hpp"
#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/gnuplot_plot.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>

namespace sinew::cli {
namespace {

/// The suite of constitutive-model throughput runs, beside the NLP suites.
const char* const kKernelSuite = "kernels";
/// The suite of strategy comparisons (strategies_bench.hpp).
const char* const kStrategiesSuite = "strategies";
/// The suite of factorization reuse, off against on, on every scene (reuse_bench.hpp).
const char* const kReuseSuite = "reuse";
/// The suite of rig fits on generated faces (rig_bench.hpp).
const char* const kRigSuite = "rig";
/// The suite of scenes stepped in time, each under every integrator (dynamics_bench.hpp).
const char* const kDynamicsSuite = "dynamics";
/// The suite of the material point method's steps (mpm_bench.hpp).
const char* const kMpmSuite = "mpm";
/// The suite of AnisoMPM's scenes (anisompm_bench.hpp).
const char* const kAnisompmSuite = "anisompm";

struct BenchFlags {
    std::string suite = "all";
    std::vector<std::string> solvers;
    std::vector<std::string> problems;
    std::string json;
    std::string output = "strategies-output";
    bool no_plots = false;
    ReferenceTolerances reference;
    long kernel_evaluations = 1000000;
    std::vector<int> rig_tets = {20000, 100000};
    bool rig_contact = false;
    SolverFlags solver_flags;
};

bool contains(const std::vector<std::string>& list, const std::string& name)
{
    return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
}

/// A markdown table after a blank line: its header (and separator) lines,
/// then the rows; nothing when there are no rows.
void print_table(const std::string& header, const std::vector<std::string>& rows)
{
    if (rows.empty())
        return;
    std::cout << "\n" << header << "\n";
    for (const std::string& row : rows)
        std::cout << row << "\n";
}

/// One column of the bench: a solver with backend options of its own (relaxed
/// KKT at two stiffnesses), labelled for the tables.
struct Strategy {
    std::string label;
    std::string solver;
    std::map<std::string, std::string> backend;
};

/// The solvers suite constrained compares (unless --solver chooses): those
/// for equality constraints and bounds.
const std::vector<std::string> kConstrainedStrategies = {
    "ipopt", "nlopt-slsqp", "nlopt-auglag", "kkt-newton", "interior-point", "relaxed-kkt", "penalty", "augmented-lagrangian"};

/// Every solver chosen, once; relaxed-kkt at κ = 1e4 and 1e8 in suite
/// constrained, where its finite-κ violation is what the comparison shows.
std::vector<Strategy> bench_strategies(const BenchFlags& flags)
{
    std::vector<Strategy> strategies;
    for (const auto& solver : all_solvers()) {
        if (!contains(flags.solvers, solver->name()))
            continue;
        if (flags.solvers.empty() && flags.suite == "constrained" &&
            !contains(kConstrainedStrategies, solver->name()))
            continue;
        if (solver->name() == "relaxed-kkt" && flags.suite == "constrained") {
            strategies.push_back({"relaxed-kkt κ=1e4", solver->name(), {{"kappa", "1e4"}}});
            strategies.push_back({"relaxed-kkt κ=1e8", solver->name(), {{"kappa", "1e8"}}});
        } else {
            strategies.push_back({solver->name(), solver->name(), {}});
        }
    }
    return strategies;
}

/// Suite constrained holds every Hock-Schittkowski problem with constraints or
/// bounds: its own and the constrained ones of suite classic.
bool in_suite(const BuiltinProblem& problem, const std::string& suite)
{
    if (suite == "all" || problem.suite == suite)
        return true;
    return suite == "constrained" && problem.suite == "classic" && problem.name.rfind("hs", 0) == 0;
}

/// Iterations and time of each strategy on each problem (unsolved or
/// refused: +∞), for the performance profiles.
struct ProfileData {
    std::vector<StrategyCosts> iterations, time;
};

/// One run of a strategy on a built-in problem: the result (a load-stepped
/// scene's last step), and for a scene its totals over the load steps and
/// its contact with the scene's bodies.
struct StrategyRun {
    Result result;
    int total_iterations = 0;
    double total_time_s = 0.0;
    ContactSummary contact;
};

/// A built-in scene runs through the scene runner (the one way a scene is
/// run), any other problem through solve().
StrategyRun run_strategy(const BuiltinProblem& problem, const std::string& solver, const SolverOptions& options)
{
    if (problem.scene.empty()) {
        const std::unique_ptr<Nlp> nlp = problem.make();
        Result result = solve(*nlp, solver, options);
        const int iterations = result.iterations;
        const double time_s = result.time_s;
        return {std::move(result), iterations, time_s, ContactSummary{}};
    }
    Scene scene = make_builtin_scene(problem.scene);
    SceneRunRequest request;
    request.solver = solver;
    request.options = options;
    SceneRunOutcome outcome = run_scene(scene, resolve_scene_run(scene, request).settings);
    return {std::move(outcome.last), outcome.total_iterations, outcome.total_time_s, outcome.contact};
}

/// A row of the contact table: the run's totals over its load steps and the
/// bodies' push on the mesh at its last solution.
std::string contact_row(const std::string& problem, const std::string& strategy, const StrategyRun& run)
{
    const ContactSummary& c = run.contact;
    return "| " + problem + " | " + strategy + " | " + to_string(run.result.status) + " | " +
           std::to_string(run.total_iterations) + " | " + table_cell("%.3f", run.total_time_s) + " | " +
           table_cell("%.6g", c.force.norm()) + " | " + table_cell("%.6g", c.force.z()) + " | " +
           table_cell("%.2e", c.max_penetration) + " | " + std::to_string(c.contact_nodes) + " | " +
           table_cell("%.4g", c.contact_radius) + " |";
}

std::string newton_row(const std::string& problem, const std::string& strategy, const Result& result)
{
    // Newton's own accounting against the direct-solver limit:
    // total ≥ iterations × one numeric factorization.
    const auto& st = result.statistics;
    const double one_factorization = st.at("factorization_s") / st.at("factorizations");
    return "| " + problem + " | " + strategy + " | " + std::to_string(result.iterations) + " | " +
           table_cell("%.0f", st.at("factorizations")) + " | " + table_cell("%.4f", st.at("assembly_s") / result.iterations) +
           " | " + table_cell("%.4f", one_factorization) + " | " + table_cell("%.3f", result.time_s) + " | " +
           table_cell("%.2f", result.time_s / (result.iterations * one_factorization)) + " |";
}

/// Every built-in problem of the chosen suite × every strategy that accepts it,
/// as a markdown table; true when every run reached its reference.
bool run_problems(const BenchFlags& flags, const SolverOptions& options, nlohmann::json& runs)
{
    std::cout << "| problem | solver | status | iterations | factorizations | objective | f* rel. error "
                 "| constraint violation | KKT residual | time (s) | reached f* |\n"
              << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    const std::vector<Strategy> strategies = bench_strategies(flags);
    std::vector<std::string> skipped, newton_rows, contact_rows;
    ProfileData profile;
    for (const Strategy& s : strategies) {
        profile.iterations.push_back({s.label, {}});
        profile.time.push_back({s.label, {}});
    }
    std::vector<char> accepted_any(strategies.size(), 0);
    bool all_good = true;
    for (const auto& problem : builtin_problems()) {
        if (!in_suite(problem, flags.suite) || !contains(flags.problems, problem.name))
            continue;
        std::vector<double> iterations, times;
        for (size_t k = 0; k < strategies.size(); ++k) {
            const Strategy& strategy = strategies[k];
            const std::unique_ptr<Nlp> nlp = problem.make();
            if (const auto why = find_solver(strategy.solver).refusal(*nlp)) {
                skipped.push_back(problem.name + " × " + strategy.label + ": " + *why);
                iterations.push_back(kUnsolved);
                times.push_back(kUnsolved);
                continue;
            }
            accepted_any[k] = 1;
            SolverOptions run_options = options;
            for (const auto& [key, value] : strategy.backend)
                run_options.backend[key] = value;
            const StrategyRun run = run_strategy(problem, strategy.solver, run_options);
            const Result& result = run.result;
            if (run.contact.present)
                contact_rows.push_back(contact_row(problem.name, strategy.label, run));
            const double error = optimum_error(problem, result);
            const bool good = reaches_reference(problem, result, flags.reference);
            all_good = all_good && good;
            const auto& st = result.statistics;
            const bool factorized = st.count("factorizations") && st.at("factorizations") > 0;
            std::cout << "| " << problem.name << " | " << strategy.label << " | " << to_string(result.status)
                      << " | " << result.iterations << " | "
                      << (factorized ? table_cell("%.0f", st.at("factorizations")) : "-") << " | "
                      << table_cell("%.10g", result.objective) << " | " << table_cell("%.1e", error) << " | "
                      << table_cell("%.1e", result.constraint_violation) << " | " << table_cell("%.1e", result.kkt_residual)
                      << " | " << table_cell("%.4f", result.time_s) << " | " << (good ? "yes" : "no") << " |"
                      << std::endl;
            if (factorized && result.iterations > 0)
                newton_rows.push_back(newton_row(problem.name, strategy.label, result));
            iterations.push_back(good ? result.iterations : kUnsolved);
            times.push_back(good ? result.time_s : kUnsolved);
            nlohmann::json json_run = to_json(result);
            json_run["suite"] = problem.suite;
            json_run["strategy"] = strategy.label;
            json_run["reference_objective"] =
                problem.reference_objective ? number(*problem.reference_objective) : nlohmann::json();
            json_run["optimum_relative_error"] = number(error);
            json_run["reached_reference"] = good;
            json_run["total_iterations"] = run.total_iterations;
            json_run["total_time_s"] = number(run.total_time_s);
            if (run.contact.present)
                json_run["contact"] = to_json(run.contact);
            runs.push_back(json_run);
        }
        for (size_t s = 0; s < strategies.size(); ++s) {
            profile.iterations[s].costs.push_back(iterations[s]);
            profile.time[s].costs.push_back(times[s]);
        }
    }
    print_table("| problem | solver | iterations | factorizations | assembly per iteration (s) "
                "| one factorization (s) | total (s) | total / (iterations × one factorization) |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|",
                newton_rows);
    print_table("| problem | solver | status | iterations (all load steps) | time, all load steps (s) "
                "| contact force \\|F\\| (N) | F_z (N) | max penetration (m) | contact nodes | contact radius (m) |\n"
                "|---|---|---|---:|---:|---:|---:|---:|---:|---:|",
                contact_rows);
    // Strategies that accepted no problem of the suite are left out of the profiles.
    std::vector<StrategyCosts> iteration_costs, time_costs;
    for (size_t k = 0; k < strategies.size(); ++k)
        if (accepted_any[k]) {
            iteration_costs.push_back(profile.iterations[k]);
            time_costs.push_back(profile.time[k]);
        }
    if (iteration_costs.size() > 1 && !iteration_costs.front().costs.empty()) {
        const std::vector<double> taus = {1, 2, 4, 8, 16};
        std::cout << "\nDolan-Moré performance profile ρ(τ) over the " << iteration_costs.front().costs.size()
                  << " problems (solved: reached f*; refused or not solved counts as unsolved), iterations:\n\n"
                  << performance_profile_table(iteration_costs, taus) << "\ntime:\n\n"
                  << performance_profile_table(time_costs, taus);
    }
    if (!skipped.empty())
        std::cout << "\n";
    for (const auto& line : skipped)
        std::cout << "- not applicable: " << line << "\n";
    return all_good;
}

/// Throughput of every constitutive model, as a markdown table; false when a
/// model's output was not finite (its time is not a throughput then).
bool run_kernels(const BenchFlags& flags, nlohmann::json& kernels)
{
    std::cout << "\n| model | F | evaluations | time (s) | evaluations/s (psi + P + projected dP/dF, one core) |\n"
              << "|---|---|---:|---:|---:|\n";
    bool all_finite = true;
    for (const KernelRun& run : run_kernel_benchmarks(flags.kernel_evaluations, 2026)) {
        const bool finite = std::isfinite(run.checksum);
        all_finite = all_finite && finite;
        std::cout << "| " << run.model << " | " << run.shape << " | " << run.evaluations << " | "
                  << table_cell("%.3f", run.time_s) << " | "
                  << (finite ? table_cell("%.3g", run.evaluations_per_second) : "FAILED: non-finite output") << " |"
                  << std::endl;
        kernels.push_back({{"model", run.model},
                           {"shape", run.shape},
                           {"evaluations", run.evaluations},
                           {"time_s", number(run.time_s)},
                           {"evaluations_per_second", number(run.evaluations_per_second)},
                           {"checksum", number(run.checksum)},
                           {"finite", finite}});
    }
    return all_finite;
}

} // namespace

void add_bench_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "bench", "run every built-in problem of a suite with every solver that accepts it and print a markdown "
                 "table (suite kernels: throughput of every constitutive model); exit 0 when every run reached "
                 "the published optimum f* (feasible, at f*, stopped on its own criterion; converged where there "
                 "is no f*), 3 otherwise");
    auto flags = std::make_shared<BenchFlags>();
    command->add_option("--suite", flags->suite, "suite name (see sinew list), kernels, strategies, reuse, rig, mpm, anisompm, or all")
        ->capture_default_str();
    command->add_option("--output", flags->output,
                        "suite strategies: folder for each problem's comparison and the performance profiles")
        ->capture_default_str();
    command->add_flag("--no-plots", flags->no_plots, "suite strategies: tables and JSON only");
    command->add_option("--solver", flags->solvers,
                        "only these solvers (repeatable); suite rig: a strategy's label too, such as "
                        "\"ipopt (Gauss-Newton)\"");
    command->add_option("--problem", flags->problems, "only these problems (repeatable)");
    command->add_option("--json", flags->json, "write every run's full result to this file");
    command->add_option("--optimum-tol", flags->reference.objective,
                        "largest |f - f*| / max(1, |f*|) counted as reaching the published optimum f*")
        ->capture_default_str();
    command->add_option("--feasibility-tol", flags->reference.feasibility,
                        "largest constraint violation counted as reaching f*")
        ->capture_default_str();
    command->add_option("--evaluations", flags->kernel_evaluations,
                        "suite kernels: random deformation gradients per model")
        ->capture_default_str()
        ->check(CLI::Range(1, std::numeric_limits<int>::max()));
    command->add_option("--rig-tets", flags->rig_tets, "suite rig: the face sizes, tets aimed at (repeatable)")
        ->capture_default_str()
        ->check(CLI::Range(1000, 2000000));
    command->add_flag("--rig-contact", flags->rig_contact,
                      "suite rig: the faces pressed against their skulls (the seed's collision penalty, §5.7)");
    add_solver_flags(*command, flags->solver_flags);

    command->callback([flags, &exit_code] {
        const SolverOptions options = to_solver_options(flags->solver_flags);
        require_positive_finite(flags->reference.objective, "--optimum-tol");
        require_positive_finite(flags->reference.feasibility, "--feasibility-tol");
        if (!flags->json.empty())
            check_writable(flags->json);  // fail on a bad path before the solve, not after
        const auto suites = builtin_suites();
        const bool kernels_only = flags->suite == kKernelSuite;
        const bool strategies = flags->suite == kStrategiesSuite;
        const bool reuse = flags->suite == kReuseSuite;
        const bool rig = flags->suite == kRigSuite;
        if (flags->suite != "all" && !kernels_only && !strategies && !reuse && !rig && flags->suite != kMpmSuite &&
            flags->suite != kAnisompmSuite &&
            std::find(suites.begin(), suites.end(), flags->suite) == suites.end()) {
            std::string valid = "all";
            for (const auto& s : suites)
                valid += ", " + s;
            throw InputError("unknown suite '" + flags->suite + "'; valid suites: " + valid + ", " + kKernelSuite +
                             ", " + kStrategiesSuite + ", " + kReuseSuite + ", " + kRigSuite + ", " + kMpmSuite + ", " +
                             kAnisompmSuite);
        }
        if (rig)
            check_rig_strategies(flags->solvers, options);
        else if (flags->rig_contact)
            throw InputError("--rig-contact applies to suite rig only");
        else
            for (const auto& name : flags->solvers)
                find_solver(name);
        for (const auto& name : flags->problems)
            find_builtin_problem(name);
        if (reuse) {
            if (!flags->solvers.empty())
                throw InputError("suite reuse chooses its solvers (projected-newton, augmented-lagrangian); drop --solver");
            for (const auto& name : flags->problems)
                builtin_scene_text(name);  // scenes only: InputError naming the valid ones
            nlohmann::json runs = nlohmann::json::array();
            const bool converged = run_reuse_bench(flags->problems, options, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = converged ? 0 : 3;
            return;
        }
        if (flags->suite == kMpmSuite) {
            if (!flags->solvers.empty() || !flags->problems.empty())
                throw InputError("suite mpm chooses its runs and the scenes' solvers; drop --solver and --problem");
            nlohmann::json runs = nlohmann::json::array();
            const bool converged = run_mpm_bench(options, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = converged ? 0 : 3;
            return;
        }
        if (flags->suite == kAnisompmSuite) {
            if (!flags->solvers.empty() || !flags->problems.empty())
                throw InputError("suite anisompm runs the scenes of scenes/anisompm as they are; drop --solver and --problem");
            nlohmann::json runs = nlohmann::json::array();
            const bool converged = run_anisompm_bench(options, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = converged ? 0 : 3;
            return;
        }
        if (flags->suite == kDynamicsSuite) {
            if (flags->solvers.size() > 1)
                throw InputError("suite dynamics runs one solver (the scene's, or one --solver)");
            for (const auto& name : flags->problems)
                if (!builtin_scene_file(name).dynamic)
                    throw InputError("'" + name + "' is not a scene of suite dynamics");
            const std::optional<std::string> solver =
                flags->solvers.empty() ? std::nullopt : std::optional<std::string>(flags->solvers.front());
            nlohmann::json runs = nlohmann::json::array();
            const bool converged = run_dynamics_bench(flags->problems, solver, options, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = converged ? 0 : 3;
            return;
        }
        if (rig) {
            if (!flags->problems.empty())
                throw InputError("suite rig generates its faces; drop --problem (choose sizes with --rig-tets)");
            nlohmann::json runs = nlohmann::json::array();
            const bool converged = run_rig_bench(flags->rig_tets, flags->solvers, options, flags->rig_contact, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = converged ? 0 : 3;
            return;
        }
        if (strategies) {
            if (!flags->no_plots && !gnuplot_available())
                throw InputError(gnuplot_missing_message());
            std::error_code error;
            std::filesystem::create_directories(flags->output, error);
            if (error)
                throw InputError("cannot create output folder '" + flags->output + "': " + error.message());
            nlohmann::json runs = nlohmann::json::array();
            const bool referenced =
                run_strategies_bench(flags->output, flags->solvers, flags->problems, options, !flags->no_plots, runs);
            if (!flags->json.empty())
                write_text_file(flags->json, nlohmann::json{{"suite", flags->suite}, {"runs", runs}}.dump(2) + "\n");
            exit_code = referenced ? 0 : 3;
            return;
        }

        nlohmann::json runs = nlohmann::json::array();
        nlohmann::json kernels = nlohmann::json::array();
        bool all_good = true;
        if (!kernels_only)
            all_good = run_problems(*flags, options, runs);
        const bool filtered = !flags->solvers.empty() || !flags->problems.empty();
        if (kernels_only || (flags->suite == "all" && !filtered))
            all_good = run_kernels(*flags, kernels) && all_good;
        if (!flags->json.empty())
            write_text_file(flags->json,
                            nlohmann::json{{"suite", flags->suite}, {"runs", runs}, {"kernels", kernels}}.dump(2) +
                                "\n");
        exit_code = all_good ? 0 : 3;
    });
}

} // namespace sinew::cli
