#include "cli_options.hpp"
#include "commands.hpp"
#include "output_file.hpp"
#include "result_json.hpp"

#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew::cli {

void add_solve_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "solve", "solve a problem with one solver; exit 0 when converged, 3 when not (the result is written either way)");
    struct Flags {
        std::string problem;
        std::string solver = "ipopt";
        std::string json;
        int verbosity = 1;
        SolverFlags solver_flags;
    };
    auto flags = std::make_shared<Flags>();
    command->add_option("problem", flags->problem, "built-in problem name (see sinew list)")->required();
    command->add_option("--solver", flags->solver, "solver name (see sinew list)")->capture_default_str();
    command->add_option("--json", flags->json, "write the result (status, x, multipliers, history, ...) to this file");
    command->add_option("--verbosity", flags->verbosity, "0 silent, 1 iteration table, 2 backend output")
        ->capture_default_str();
    add_solver_flags(*command, flags->solver_flags);

    command->callback([flags, &exit_code] {
        SolverOptions options = to_solver_options(flags->solver_flags);
        options.verbosity = flags->verbosity;
        if (!flags->json.empty())
            write_text_file(flags->json, "");  // fail on a bad path before the solve, not after
        const BuiltinProblem& problem = find_builtin_problem(flags->problem);
        find_solver(flags->solver);
        const std::unique_ptr<Nlp> nlp = problem.make();
        const Result result = solve(*nlp, flags->solver, options);
        if (!flags->json.empty())
            write_text_file(flags->json, to_json(result).dump(2) + "\n");
        exit_code = result.status == Status::converged ? 0 : 3;
    });
}

} // namespace sinew::cli
