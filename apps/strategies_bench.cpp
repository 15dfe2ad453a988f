#include "strategies_bench.hpp"

#include "comparison_progress.hpp"

#include "sinew/bench/performance_profile.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/runs/comparison_report.hpp"
#include "sinew/runs/comparison_subjects.hpp"
#include "sinew/runs/result_json.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

namespace sinew::cli {
namespace {

/// The problems of the suite: the inextensibility scenes, then the
/// Hock-Schittkowski problems with equality constraints or bounds.
bool in_strategies_suite(const BuiltinProblem& problem)
{
    const bool hs = problem.name.rfind("hs", 0) == 0 && (problem.suite == "classic" || problem.suite == "constrained");
    return problem.suite == "inextensibility" || hs;
}

/// The profile's name for a run: its label, or for a κ sweep the solver and
/// the run's place in it ("relaxed-kkt κ2").
std::string profile_label(const Comparison& comparison, const ComparisonRun& run)
{
    if (!run.strategy.kappa)
        return run.strategy.label;
    const auto sweep = kappa_sweep(comparison, run.strategy.solver);
    const auto place = std::find(sweep.begin(), sweep.end(), &run) - sweep.begin();
    return run.strategy.solver + " κ" + std::to_string(place + 1);
}

/// Iterations and time per profile label and problem (+∞ unless converged).
struct ProfileCosts {
    std::vector<std::string> labels;
    std::map<std::string, std::vector<double>> iterations, time;

    void add(const Comparison& comparison, size_t problem, size_t problems)
    {
        for (const ComparisonRun& run : comparison.runs) {
            const std::string label = profile_label(comparison, run);
            if (!iterations.count(label)) {
                labels.push_back(label);
                iterations[label].assign(problems, kUnsolved);
                time[label].assign(problems, kUnsolved);
            }
            if (run.result.status == Status::converged) {
                iterations[label][problem] = run.result.iterations;
                time[label][problem] = run.result.time_s;
            }
        }
    }

    std::vector<StrategyCosts> of(const std::map<std::string, std::vector<double>>& costs) const
    {
        std::vector<StrategyCosts> out;
        for (const auto& label : labels)
            out.push_back({label, costs.at(label)});
        return out;
    }
};

void report_profiles(const ProfileCosts& costs, size_t problems, const std::string& folder, bool plots)
{
    const std::vector<double> taus = {1, 2, 4, 8, 16};
    std::cout << "\nDolan-Moré performance profile ρ(τ) over the " << problems
              << " problems (solved: converged; refused or not solved counts as unsolved), iterations:\n\n"
              << performance_profile_table(costs.of(costs.iterations), taus) << "\ntime:\n\n"
              << performance_profile_table(costs.of(costs.time), taus);
    if (!plots)
        return;
    draw_plot(performance_profile_plot(costs.of(costs.iterations), "performance profile: iterations"), folder,
              "profile_iterations");
    draw_plot(performance_profile_plot(costs.of(costs.time), "performance profile: wall time"), folder,
              "profile_time");
}

} // namespace

bool run_strategies_bench(const std::string& folder, const std::vector<std::string>& solvers,
                          const std::vector<std::string>& problems, const SolverOptions& options, bool plots,
                          nlohmann::json& runs)
{
    std::vector<const BuiltinProblem*> chosen;
    for (const BuiltinProblem& problem : builtin_problems())
        if (in_strategies_suite(problem) &&
            (problems.empty() || std::find(problems.begin(), problems.end(), problem.name) != problems.end()))
            chosen.push_back(&problem);
    ProfileCosts costs;
    bool all_referenced = true;
    for (size_t p = 0; p < chosen.size(); ++p) {
        const ComparisonSubject subject = builtin_subject(*chosen[p]);
        std::vector<std::string> refusals;
        const auto strategies =
            comparison_strategies(*subject.make_nlp(), solvers, default_kappas(*subject.make_nlp()), refusals);
        const Comparison comparison =
            run_comparison(subject, strategies, options, comparison_progress(std::cerr, subject.name));
        const std::string subfolder = folder + "/" + subject.name;
        std::filesystem::create_directories(subfolder);
        write_comparison(comparison, subfolder, plots);
        std::cout << "\n### " << subject.name << "\n\n" << comparison_markdown(comparison) << std::flush;
        for (const auto& why : refusals)
            std::cout << "- not applicable: " << why << "\n";
        costs.add(comparison, p, chosen.size());
        all_referenced = all_referenced && !comparison.reference.empty();
        for (const ComparisonRun& run : comparison.runs) {
            nlohmann::json entry = to_json(run.result);
            entry["strategy"] = run.strategy.label;
            entry["profile_label"] = profile_label(comparison, run);
            entry["reference_distance"] = number(run.reference_distance);
            runs.push_back(entry);
        }
    }
    report_profiles(costs, chosen.size(), folder, plots);
    return all_referenced;
}

} // namespace sinew::cli
