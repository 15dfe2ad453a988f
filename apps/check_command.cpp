#include "cli_options.hpp"
#include "commands.hpp"

#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/derivative_check.hpp"

#include <iostream>
#include <memory>
#include <random>

namespace sinew::cli {

void add_check_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "check", "compare gradient, Jacobian and Hessian of the Lagrangian with central finite differences; "
                 "exit 0 when every worst relative error is within --tol, 3 otherwise");
    struct Flags {
        std::string problem;
        double tolerance = 1e-5;
        double perturbation = 0.0;
        double step = 1e-6;
        unsigned seed = 7;
    };
    auto flags = std::make_shared<Flags>();
    command->add_option("problem", flags->problem, "built-in problem name (see sinew list)")->required();
    command->add_option("--tol", flags->tolerance, "largest accepted relative error")->capture_default_str();
    command->add_option("--perturb", flags->perturbation,
                        "check at x0 + perturb·u, u uniform in [-1, 1]^n, instead of the starting point x0")
        ->capture_default_str();
    command->add_option("--step", flags->step, "central-difference step (scaled by max(1, |x_i|))")
        ->capture_default_str();
    command->add_option("--seed", flags->seed, "seed of the perturbation and of the random multipliers")
        ->capture_default_str();

    command->callback([flags, &exit_code] {
        require_positive_finite(flags->tolerance, "--tol");
        require_non_negative_finite(flags->perturbation, "--perturb");
        require_positive_finite(flags->step, "--step");
        const BuiltinProblem& problem = find_builtin_problem(flags->problem);
        const std::unique_ptr<Nlp> nlp = problem.make();
        Eigen::VectorXd x = nlp->starting_point();
        std::mt19937 rng(flags->seed);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (Eigen::Index i = 0; i < x.size(); ++i)
            x[i] += flags->perturbation * uniform(rng);
        DerivativeCheckOptions options;
        options.step = flags->step;
        options.seed = flags->seed;
        const DerivativeCheckReport report = check_derivatives(*nlp, x, options);
        const bool passed = report.passed(flags->tolerance);
        std::cout << "derivative check of " << problem.name << " (n = " << nlp->num_variables()
                  << ", m = " << nlp->num_constraints() << ")\n"
                  << report.to_text() << "\n"
                  << (passed ? "passed" : "FAILED") << " (tolerance " << flags->tolerance << ")\n";
        exit_code = passed ? 0 : 3;
    });
}

} // namespace sinew::cli
