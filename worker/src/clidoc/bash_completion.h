// SPDX-License-Identifier: GPL-3.0-or-later
// A bash completion script written from a command line's definition
// (cli_tree.h): the first word completes to a command, "-" to the current
// command's options, an option with choices ({local,slurm}) to its choices;
// anything else falls back to file names.
#pragma once

#include <string>

#include "clidoc/cli_tree.h"

namespace gridfree {

// The script for `program` (source it, or install it as
// share/bash-completion/completions/<program>).
std::string bash_completion(const CliCommand& tree, const std::string& program);

}  // namespace gridfree
