// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker: solves one frozen-bed case on one grid (docs/INTERFACE.md §2).
// main parses, runs one subcommand, and maps the outcome to an exit code.
#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "cli_docs.h"
#include "commands.h"
#include "clidoc/doc_request.h"
#include "core/command_suggestion.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "core/version.h"
#include "openmp_waiting.h"

int main(int argc, char** argv) {
  using namespace gridfree;
  worker_cli::use_default_openmp_waiting(argv);
  spdlog::set_default_logger(spdlog::stderr_color_mt("gridfree-worker"));
  spdlog::set_pattern("%^[%l]%$ %v");

  CLI::App app{"gridfree-worker: steady gas flow through one frozen particle bed on one grid", "gridfree-worker"};
  const std::string version = program_version_string("gridfree-worker");
  app.set_version_flag("--version,-V", version);
  app.require_subcommand(1);
  int exit_code = to_int(ExitCode::kOk);
  worker_cli::add_solve_command(app, exit_code);
  worker_cli::add_particles_command(app, exit_code);
  worker_cli::add_verify_command(app, exit_code);
  worker_cli::add_align_command(app, exit_code);
  worker_cli::add_collect_command(app, exit_code);
  app.add_subcommand("version", "print the version (as --version)")->callback([&version] {
    std::cout << version << '\n';
  });
  // `--man-page` / `--bash-completion`: the build writes the installed docs from this definition.
  if (int code = 0; cli_docs_requested(app, argc, argv, worker_cli::worker_man_page_info(), std::cout, std::cerr, code)) return code;
  // A mistyped command: name it and the nearest known one (exit 2).
  if (report_unknown_command(app, argc, argv)) return to_int(ExitCode::kInvalidInput);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : to_int(ExitCode::kInvalidInput);
  } catch (const InputError& e) {
    std::cerr << error_lines(e);
    return to_int(ExitCode::kInvalidInput);
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << '\n';
    return to_int(ExitCode::kInternalError);
  }
  return exit_code;
}
