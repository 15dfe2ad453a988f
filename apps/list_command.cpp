#include "commands.hpp"

#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/solvers/solver.hpp"

#include <iomanip>
#include <iostream>
#include <memory>

namespace sinew::cli {
namespace {

void list_everything()
{
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
    std::cout << "options of a solver: sinew list --solver NAME\n";
}

/// One solver's options as it declares them (DESIGN.md, "Options").
void list_solver(const Solver& solver)
{
    std::cout << solver.name() << ": " << solver.description() << "\n";
    const std::vector<OptionDeclaration> declared = solver.declared_options();
    if (declared.empty()) {
        std::cout << "options: passed by name to the backend, which checks them (--option name=value)\n";
        return;
    }
    std::cout << "options (--option name=value):\n" << describe_options(declared);
    for (const auto& [prefix, nested] : solver.nested_options())
        std::cout << "options of the nested solver '" << prefix << "' (--option " << prefix << ".name=value):\n"
                  << describe_options(nested);
}

} // namespace

void add_list_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand("list", "list the built-in problems (by suite) and the solvers");
    auto solver = std::make_shared<std::string>();
    command->add_option("--solver", *solver, "list this solver's options: name, type, range, default, doc");
    auto scene_keys = std::make_shared<bool>(false);
    command->add_flag("--scene-keys", *scene_keys,
                      "list every key of a scene file, part by part: type, range or choices, default, doc (markdown)");
    command->callback([&exit_code, solver, scene_keys] {
        if (*scene_keys)
            std::cout << scene_keys_markdown();
        else if (solver->empty())
            list_everything();
        else
            list_solver(find_solver(*solver));
        exit_code = 0;
    });
}

} // namespace sinew::cli
