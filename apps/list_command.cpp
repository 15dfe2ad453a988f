#include "commands.hpp"

#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/solver.hpp"

#include <iomanip>
#include <iostream>

namespace sinew::cli {

void add_list_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand("list", "list the built-in problems (by suite) and the solvers");
    command->callback([&exit_code] {
        std::cout << "problems:\n";
        for (const auto& suite : builtin_suites()) {
            std::cout << "  suite " << suite << "\n";
            for (const auto& p : builtin_problems())
                if (p.suite == suite)
                    std::cout << "    " << std::left << std::setw(25) << p.name << " " << p.description << "\n";
        }
        std::cout << "solvers:\n";
        for (const auto& s : all_solvers())
            std::cout << "  " << std::left << std::setw(27) << s->name() << " " << s->description() << "\n";
        exit_code = 0;
    });
}

} // namespace sinew::cli
