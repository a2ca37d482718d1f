// Subcommands of gridfree-worker. Each add_*_command registers itself on the
// app and, when selected, stores its exit code in `exit_code`.
#pragma once

#include <CLI/CLI.hpp>

namespace gridfree::worker_cli {

void add_solve_command(CLI::App& app, int& exit_code);
void add_particles_command(CLI::App& app, int& exit_code);
void add_verify_command(CLI::App& app, int& exit_code);
void add_align_command(CLI::App& app, int& exit_code);

}  // namespace gridfree::worker_cli
