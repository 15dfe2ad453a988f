#include "cli_options.hpp"
#include "commands.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <utility>

namespace sinew::cli {
namespace {

struct CheckFlags {
    std::string problem;
    double tolerance = 1e-5;
    double perturbation = 0.0;
    double step = 1e-6;
    unsigned seed = 7;
    int points = 0;      // 0: 3 for n <= kMaxCheckedVariables, 2 above
    int directions = 0;  // 0: 2 for n <= kMaxCheckedVariables, 1 above
    int steps = 10;
    double initial_step = 1e-2;
    double point_perturbation = 1e-3;
    double min_slope = 1.8;
    bool series = false;
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The Taylor test at x with the flags' counts; prints its table. True when it passed.
bool run_taylor_test(Nlp& nlp, const Eigen::VectorXd& x, const CheckFlags& flags)
{
    const bool large = nlp.num_variables() > kMaxCheckedVariables;
    TaylorOptions options;
    options.points = flags.points != 0 ? flags.points : (large ? 2 : 3);
    options.directions = flags.directions != 0 ? flags.directions : (large ? 1 : 2);
    options.steps = flags.steps;
    options.initial_step = flags.initial_step;
    options.perturbation = flags.point_perturbation;
    options.min_slope = flags.min_slope;
    options.seed = flags.seed;
    const auto start = std::chrono::steady_clock::now();
    const TaylorReport report = taylor_test(nlp, x, options);
    std::cout << report.to_text() << "  (" << std::setprecision(3) << seconds_since(start) << " s)\n";
    if (flags.series || !report.passed())
        std::cout << report.series_text();
    return report.passed();
}

/// The entrywise check at x, or one line saying why it was skipped. True
/// when it passed or was skipped.
bool run_entrywise_check(Nlp& nlp, const Eigen::VectorXd& x, const CheckFlags& flags)
{
    if (const std::string refusal = dense_check_refusal(nlp); !refusal.empty()) {
        std::cout << "entrywise check skipped: " << refusal << "\n";
        return true;
    }
    DerivativeCheckOptions options;
    options.step = flags.step;
    options.seed = flags.seed;
    options.tolerance = flags.tolerance;
    const auto start = std::chrono::steady_clock::now();
    const DerivativeCheckReport report = check_derivatives(nlp, x, options);
    const bool passed = report.passed(flags.tolerance);
    std::cout << "entrywise check (central differences), " << (passed ? "passed" : "FAILED") << " at tolerance "
              << flags.tolerance << " (" << std::setprecision(3) << seconds_since(start) << " s)\n"
              << report.to_text() << "\n";
    return passed;
}

void run_check(const CheckFlags& flags, int& exit_code)
{
    require_positive_finite(flags.tolerance, "--tol");
    require_non_negative_finite(flags.perturbation, "--perturb");
    require_positive_finite(flags.step, "--step");
    require_positive_finite(flags.initial_step, "--h0");
    require_positive_finite(flags.min_slope, "--min-slope");
    require_non_negative_finite(flags.point_perturbation, "--spread");
    for (const auto& [value, flag] : {std::pair{flags.points, "--points"}, std::pair{flags.directions, "--directions"}})
        if (value < 0)
            throw InputError(std::string(flag) + " = " + std::to_string(value) + " is invalid; it must be >= 0");
    const BuiltinProblem& problem = find_builtin_problem(flags.problem);
    const std::unique_ptr<Nlp> nlp = problem.make();
    Eigen::VectorXd x = nlp->starting_point();
    std::mt19937 rng(flags.seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x[i] += flags.perturbation * uniform(rng);
    std::cout << "derivative check of " << problem.name << " (n = " << nlp->num_variables()
              << ", m = " << nlp->num_constraints() << ")\n";
    const bool taylor_passed = run_taylor_test(*nlp, x, flags);
    const bool entrywise_passed = run_entrywise_check(*nlp, x, flags);
    const bool passed = taylor_passed && entrywise_passed;
    std::cout << (passed ? "passed" : "FAILED") << "\n";
    exit_code = passed ? 0 : 3;
}

} // namespace

void add_check_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "check", "check gradient, Jacobian and Hessian of the Lagrangian: a sparse Taylor test (remainder slopes, "
                 "always) and an entrywise comparison with central differences (when n <= 4000); exit 0 when both "
                 "pass, 3 otherwise");
    auto flags = std::make_shared<CheckFlags>();
    command->add_option("problem", flags->problem, "built-in problem name (see sinew list)")->required();
    command->add_option("--tol", flags->tolerance, "entrywise: largest accepted relative error")
        ->capture_default_str();
    command->add_option("--perturb", flags->perturbation,
                        "check at x0 + perturb·u, u uniform in [-1, 1]^n, instead of the starting point x0")
        ->capture_default_str();
    command->add_option("--step", flags->step, "entrywise: central-difference step (scaled by max(1, |x_i|))")
        ->capture_default_str();
    command->add_option("--seed", flags->seed, "seed of the perturbation, the multipliers, points and directions")
        ->capture_default_str();
    command->add_option("--points", flags->points,
                        "Taylor: points (x and random perturbations of it); 0: 3, or 2 when n > 4000")
        ->capture_default_str();
    command->add_option("--directions", flags->directions,
                        "Taylor: random directions per point; 0: 2, or 1 when n > 4000")
        ->capture_default_str();
    command->add_option("--steps", flags->steps, "Taylor: steps h0·2^-k per direction")->capture_default_str();
    command->add_option("--h0", flags->initial_step, "Taylor: first step (direction scaled by max(1, |x_i|))")
        ->capture_default_str();
    command->add_option("--spread", flags->point_perturbation,
                        "Taylor: points after the first are x + spread·u_i·max(1, |x_i|), u uniform in [-1, 1]")
        ->capture_default_str();
    command->add_option("--min-slope", flags->min_slope, "Taylor: smallest accepted remainder slope")
        ->capture_default_str();
    command->add_flag("--series", flags->series, "Taylor: print each derivative's worst series step by step");
    command->callback([flags, &exit_code] { run_check(*flags, exit_code); });
}

} // namespace sinew::cli
