// SPDX-License-Identifier: GPL-3.0-or-later
// A command line's definition as plain data, read from a CLI11 App: the
// commands, their options and positional arguments. The man page and the
// bash completion are written from it (man_page.h, bash_completion.h), so
// neither repeats an option by hand.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gridfree {

struct CliOption {
  std::vector<std::string> names;  // "-j", "--jobs" (short names first)
  std::string value;               // "INT", "TEXT:{local,slurm}", "FLOAT x 2", "TEXT ..."; "" for a flag
  std::vector<std::string> choices;  // the {a,b} of value, if any
  std::string default_value;       // shown default, or ""
  std::string description;
  bool required = false;
};

struct CliPositional {
  std::string name;  // "STUDY"
  std::string description;
  bool required = false;
  bool many = false;  // takes any number of values
};

struct CliCommand {
  std::string name;  // "" for the program itself
  std::string description;
  std::vector<CliOption> options;
  std::vector<CliPositional> positionals;
  std::vector<CliCommand> commands;  // subcommands, in definition order
};

// The definition of `app` and of every named subcommand under it; option
// groups and options or commands in the hidden group ("") are left out.
CliCommand read_cli_tree(const CLI::App& app);

}  // namespace gridfree
