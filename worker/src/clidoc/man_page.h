// SPDX-License-Identifier: GPL-3.0-or-later
// A section-1 man page (roff, man macros) written from a command line's
// definition (cli_tree.h): synopsis, the program's options, each command
// with its arguments and options, exit status, environment, see also.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "clidoc/cli_tree.h"

namespace gridfree {

struct ManPageInfo {
  std::string program;  // "gridfree"
  std::string version;  // "0.2.0"
  std::vector<std::string> description;  // DESCRIPTION paragraphs (default: the App's description)
  std::vector<std::pair<int, std::string>> exit_codes;        // code, meaning
  std::vector<std::pair<std::string, std::string>> environment;  // variable, meaning
  std::vector<std::string> see_also;                         // "gridfree-worker(1)"
};

// The man page of `tree` (read_cli_tree of the program's App).
std::string man_page(const CliCommand& tree, const ManPageInfo& info);

// `text` escaped for roff: backslashes doubled as \e, hyphens as \-, and a
// line that would start with '.' or '\'' guarded by \&.
std::string roff_escape(const std::string& text);

}  // namespace gridfree
