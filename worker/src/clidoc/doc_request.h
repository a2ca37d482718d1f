// SPDX-License-Identifier: GPL-3.0-or-later
// `PROGRAM --man-page` and `PROGRAM --bash-completion`: the man page and the
// completion script, written from the App's own definition. The build runs
// them to make the installed files (cmake/CliDocs.cmake); they are not in
// --help, which is for people.
#pragma once

#include <iosfwd>

#include "clidoc/man_page.h"

namespace CLI {
class App;
}

namespace gridfree {

// If argv[1] is --man-page or --bash-completion, writes that document of
// `app` (with no other arguments; else an error to `err`) and returns true
// (the caller exits with `exit_code`); otherwise returns false.
bool cli_docs_requested(const CLI::App& app, int argc, const char* const* argv, const ManPageInfo& info,
                        std::ostream& out, std::ostream& err, int& exit_code);

// The meaning of each ExitCode (core/exit_codes.h), for EXIT STATUS.
std::vector<std::pair<int, std::string>> exit_code_meanings();

}  // namespace gridfree
