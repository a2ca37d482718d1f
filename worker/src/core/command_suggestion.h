// SPDX-License-Identifier: GPL-3.0-or-later
// "Did you mean": the nearest of a command's known names to a mistyped one.
#pragma once

#include <algorithm>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

// Edit distance counting insertions, deletions, substitutions and swaps of
// two neighbouring characters as one edit each.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The name in `names` nearest to `word` if at most 2 edits away (and fewer
// than the name's length), else "".
std::string nearest_name(std::string_view word, const std::vector<std::string>& names);

// "unknown command 'stauts'; did you mean 'status'?" or, with no near name,
// "unknown command 'x'; commands: a, b, c".
std::string unknown_command_message(std::string_view word, const std::vector<std::string>& names);

// Before parsing: when argv[1] is neither an option nor one of the app's
// subcommands, prints the error with unknown_command_message and returns
// true (the caller exits 2). App is a CLI::App (a template, so that the core
// does not depend on CLI11).
template <class App>
bool report_unknown_command(App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  std::vector<std::string> names;
  for (const auto* sub : app.get_subcommands([](const auto*) { return true; })) names.push_back(sub->get_name());
  if (std::find(names.begin(), names.end(), argv[1]) != names.end()) return false;
  const std::string program = app.get_name().empty() ? std::string("the program") : app.get_name();
  std::cerr << "error: " << unknown_command_message(argv[1], names) << "\nrun '" << program
            << " --help' for the commands\n";
  return true;
}

}  // namespace gridfree
