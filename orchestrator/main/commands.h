// SPDX-License-Identifier: GPL-3.0-or-later
// Subcommands of gridfree. Each add_*_command registers itself on the app and,
// when selected, stores its exit code in `exit_code`.
#pragma once

#include <CLI/CLI.hpp>

namespace gridfree::cli {

void add_extrapolate_command(CLI::App& app, int& exit_code);
void add_study_commands(CLI::App& app, int& exit_code);
void add_db_command(CLI::App& app, int& exit_code);      // db check | backup | vacuum  // validate, plan, run, submit, daemon, status, report, cancel, delete, retry

}  // namespace gridfree::cli
