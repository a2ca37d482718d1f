// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree: studies -> jobs -> worker pool -> SQLite -> reports (docs/INTERFACE.md §3-§5).
// main parses, runs one subcommand, and maps the outcome to an exit code.
#include <algorithm>
#include <exception>
#include <memory>
#include <iostream>
#include <string>
#include <vector>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "cli_docs.h"
#include "cli_errors.h"

#include "commands.h"
#include "clidoc/doc_request.h"
#include "core/command_suggestion.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "core/version.h"
#include "store/sqlite.h"

int main(int argc, char** argv) {
  using namespace gridfree;
  spdlog::set_default_logger(spdlog::stderr_color_mt("gridfree"));
  spdlog::set_pattern("%^[%l]%$ %v");

  // Named: usage lines say "gridfree", not the path it was run from.
  CLI::App app{"gridfree: how much of a CFD-DEM answer is grid error", "gridfree"};
  app.failure_message(cli::failure_message);  // "error: …" like every other failure
  const std::string version = program_version_string("gridfree");
  app.set_version_flag("--version,-V", version);
  app.require_subcommand(1);
  int exit_code = to_int(ExitCode::kOk);
  cli::add_extrapolate_command(app, exit_code);
  cli::add_study_commands(app, exit_code);
  cli::add_db_command(app, exit_code);
  app.add_subcommand("version", "print the version (as --version)")->callback([&version] {
    std::cout << version << '\n';
  });
  // `gridfree help [COMMAND]`: the same text as `gridfree [COMMAND] --help`.
  auto help_topic = std::make_shared<std::string>();
  auto* help = app.add_subcommand("help", "print the help of gridfree or of COMMAND (as COMMAND --help)");
  help->add_option("COMMAND", *help_topic, "a command");
  help->callback([&app, help_topic] {
    // The formatter directly: App::help would print the help of `help` itself.
    if (help_topic->empty()) {
      std::cout << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
      return;
    }
    std::vector<std::string> names;
    for (const auto* sub : app.get_subcommands([](const auto*) { return true; })) names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), *help_topic) == names.end())
      throw InputError("help", unknown_command_message(*help_topic, names));
    const CLI::App* sub = app.get_subcommand(*help_topic);
    std::cout << app.get_formatter()->make_help(sub, app.get_name() + " " + sub->get_name(), CLI::AppFormatMode::Normal);
  });
  // `--man-page` / `--bash-completion`: the build writes the installed docs from this definition.
  if (int code = 0; cli_docs_requested(app, argc, argv, cli::gridfree_man_page_info(), std::cout, std::cerr, code)) return code;
  // A mistyped command: name it and the nearest known one (exit 2).
  if (report_unknown_command(app, argc, argv)) return to_int(ExitCode::kInvalidInput);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : to_int(ExitCode::kInvalidInput);
  } catch (const InputError& e) {
    cli::print_input_error(std::cerr, e);
    return to_int(ExitCode::kInvalidInput);
  } catch (const SqliteError& e) {
    // A database another process kept busy beyond the wait is not a bug
    // (store/busy_wait.h), nor is a damaged file (the user's input, exit 2);
    // anything else from SQLite is.
    std::cerr << (busy_code(e.code()) || damaged_code(e.code()) ? "error: " : "error: internal: ") << e.what() << '\n';
    return to_int(damaged_code(e.code()) ? ExitCode::kInvalidInput : ExitCode::kInternalError);
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << '\n';
    return to_int(ExitCode::kInternalError);
  }
  return exit_code;
}
