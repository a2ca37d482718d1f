// SPDX-License-Identifier: GPL-3.0-or-later
// The gridfree error style (see cli_errors.h).
#include "cli_errors.h"

#include <cctype>

namespace gridfree::cli {

std::string failure_message(const CLI::App* app, const CLI::Error& e) {
  std::string what = e.what();
  // "A subcommand is required" → "a subcommand …"; "STUDY is required" stays.
  if (what.size() > 1 && !std::isupper(static_cast<unsigned char>(what[1])))
    what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
  // The deepest subcommand that was given, for the help pointer.
  std::string command = app ? app->get_name() : "gridfree";
  for (const CLI::App* sub = app; sub;) {
    const auto given = sub->get_subcommands();
    if (given.empty()) break;
    sub = given.front();
    command += " " + sub->get_name();
  }
  return "error: " + what + "\nrun '" + command + " --help' for the options\n";
}

void print_input_error(std::ostream& out, const InputError& e) { out << error_lines(e); }

}  // namespace gridfree::cli
