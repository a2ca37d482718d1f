// SPDX-License-Identifier: GPL-3.0-or-later
// One error style for every gridfree failure a user causes: lines starting
// "error: ", the command-line parser's own messages included (through
// CLI11's failure-message hook), and a pointer to the help of the command.
#pragma once

#include <ostream>
#include <string>

#include <CLI/CLI.hpp>

#include "core/input_error.h"

namespace gridfree::cli {

// CLI11's failure message: "error: <message>" and "run 'gridfree [COMMAND]
// --help' for the options" (the program's name, never the path it ran from).
std::string failure_message(const CLI::App* app, const CLI::Error& e);

// Every problem of an InputError as "error: where: reason", one a line.
void print_input_error(std::ostream& out, const InputError& e);

}  // namespace gridfree::cli
