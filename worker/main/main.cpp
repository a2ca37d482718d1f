// gridfree-worker: solves one frozen-bed case on one grid (docs/INTERFACE.md §2).
// main parses, runs one subcommand, and maps the outcome to an exit code.
#include <exception>
#include <iostream>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "core/version.h"
#include "openmp_waiting.h"

int main(int argc, char** argv) {
  using namespace gridfree;
  worker_cli::use_default_openmp_waiting(argv);
  spdlog::set_default_logger(spdlog::stderr_color_mt("gridfree-worker"));
  spdlog::set_pattern("%^[%l]%$ %v");

  CLI::App app{"gridfree-worker: steady gas flow through one frozen particle bed on one grid"};
  app.set_version_flag("--version", version_string());
  app.require_subcommand(1);
  int exit_code = to_int(ExitCode::kOk);
  worker_cli::add_solve_command(app, exit_code);
  worker_cli::add_particles_command(app, exit_code);
  worker_cli::add_verify_command(app, exit_code);
  worker_cli::add_align_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : to_int(ExitCode::kInvalidInput);
  } catch (const InputError& e) {
    std::cerr << "error: invalid input\n" << e.what() << '\n';
    return to_int(ExitCode::kInvalidInput);
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << '\n';
    return to_int(ExitCode::kInternalError);
  }
  return exit_code;
}
