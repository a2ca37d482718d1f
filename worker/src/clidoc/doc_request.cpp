// SPDX-License-Identifier: GPL-3.0-or-later
#include "clidoc/doc_request.h"

#include <ostream>
#include <string>

#include <CLI/CLI.hpp>

#include "clidoc/bash_completion.h"
#include "clidoc/cli_tree.h"
#include "core/exit_codes.h"

namespace gridfree {

bool cli_docs_requested(const CLI::App& app, int argc, const char* const* argv, const ManPageInfo& info,
                        std::ostream& out, std::ostream& err, int& exit_code) {
  if (argc < 2) return false;
  const std::string what = argv[1];
  if (what != "--man-page" && what != "--bash-completion") return false;
  if (argc > 2) {
    err << "error: " << what << " takes no arguments\n";
    exit_code = to_int(ExitCode::kInvalidInput);
    return true;
  }
  const CliCommand tree = read_cli_tree(app);
  out << (what == "--man-page" ? man_page(tree, info) : bash_completion(tree, info.program));
  exit_code = to_int(ExitCode::kOk);
  return true;
}

std::vector<std::pair<int, std::string>> exit_code_meanings() {
  std::vector<std::pair<int, std::string>> out;
  for (const ExitCode c : {ExitCode::kOk, ExitCode::kInternalError, ExitCode::kInvalidInput, ExitCode::kNotConverged,
                           ExitCode::kInterrupted}) {
    std::string meaning;
    switch (c) {  // no default: a new ExitCode without a meaning is a -Wswitch warning
      case ExitCode::kOk: meaning = "success (a solve or every job of a run converged)"; break;
      case ExitCode::kInternalError: meaning = "internal error: a bug or a failure of the environment"; break;
      case ExitCode::kInvalidInput: meaning = "invalid input or configuration; the message names the field"; break;
      case ExitCode::kNotConverged:
        meaning = "ran, but did not converge, diverged, or some jobs failed (results and reports are still written)";
        break;
      case ExitCode::kInterrupted: meaning = "interrupted (SIGINT or SIGTERM); running again resumes"; break;
    }
    out.emplace_back(to_int(c), meaning);
  }
  return out;
}

}  // namespace gridfree
