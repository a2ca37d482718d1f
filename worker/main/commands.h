// SPDX-License-Identifier: GPL-3.0-or-later
// Subcommands of gridfree-worker. Each add_*_command registers itself on the
// app and, when selected, stores its exit code in `exit_code`.
#pragma once

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace gridfree::worker_cli {

void add_solve_command(CLI::App& app, int& exit_code);
void add_particles_command(CLI::App& app, int& exit_code);
void add_verify_command(CLI::App& app, int& exit_code);
void add_align_command(CLI::App& app, int& exit_code);
void add_collect_command(CLI::App& app, int& exit_code);

// `solve` of a job with /case/external (cmd_external.cpp): its exit code.
// `cores` (the --threads in effect) is the template's @@cores@@.
int run_external_solve(const std::filesystem::path& job_path, const nlohmann::json& doc, const std::string& output,
                       const std::string& progress_file, int cores);

}  // namespace gridfree::worker_cli
