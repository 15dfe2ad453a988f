// sinew: the command line. Exit codes (DESIGN.md): 0 converged, 1 internal
// error, 2 bad input, 3 not converged.
#include "commands.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
    CLI::App app{"sinew: mechanics of muscle, soft tissue and fibrous materials as nonlinear programs"};
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + "\n"; });
    // The one thread setting, before or after the command: OpenMP and OpenBLAS
    // both get it (core/threads.hpp); default every core the process may use.
    app.fallthrough();
    app.add_option_function<int>(
           "--threads", [](int count) { sinew::set_threads(count); },
           "threads for assembly (OpenMP) and dense factorization blocks (OpenBLAS), 1 to the cores this process "
           "may use (default: all of them: " + std::to_string(sinew::available_cores()) + ")")
        ->type_name("N");
    int exit_code = 0;
    sinew::cli::add_list_command(app, exit_code);
    sinew::cli::add_solve_command(app, exit_code);
    sinew::cli::add_check_command(app, exit_code);
    sinew::cli::add_compare_command(app, exit_code);
    sinew::cli::add_bench_command(app, exit_code);
    sinew::cli::add_energy_command(app, exit_code);
    sinew::cli::add_hessian_command(app, exit_code);
    sinew::cli::add_mesh_command(app, exit_code);
    if (argc > 1 && argv[1][0] != '-') {
        std::string valid;
        bool known = false;
        for (const CLI::App* command : app.get_subcommands({})) {
            valid += (valid.empty() ? "" : ", ") + command->get_name();
            known = known || command->get_name() == argv[1];
        }
        if (!known) {
            std::cerr << "sinew: unknown command '" << argv[1] << "'; valid commands: " << valid << "\n";
            return 2;
        }
    }
    try {
        sinew::set_threads(sinew::available_cores());
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "sinew: " << e.what() << " (see sinew --help)\n";
        return 2;
    } catch (const sinew::InputError& e) {
        std::cerr << "sinew: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "sinew: internal error: " << e.what() << "\n";
        return 1;
    }
    return exit_code;
}
