#pragma once
// The sinew subcommands. Each adds itself to the CLI11 application and, when
// chosen, runs and sets the process exit code:
//   0 converged / passed, 2 bad input, 3 not converged / check failed.
#include <CLI/CLI.hpp>

namespace sinew::cli {

void add_list_command(CLI::App& app, int& exit_code);
void add_solve_command(CLI::App& app, int& exit_code);
void add_check_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_energy_command(CLI::App& app, int& exit_code);
void add_hessian_command(CLI::App& app, int& exit_code);
void add_mesh_command(CLI::App& app, int& exit_code);

} // namespace sinew::cli
