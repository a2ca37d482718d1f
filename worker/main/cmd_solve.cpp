// gridfree-worker solve (placeholder until implemented).
#include <iostream>

#include "commands.h"
#include "core/exit_codes.h"

namespace gridfree::worker_cli {

void add_solve_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("solve", "not implemented yet");
  sub->callback([&exit_code] {
    std::cerr << "error: 'solve' is not implemented yet\n";
    exit_code = to_int(ExitCode::kInternalError);
  });
}

}  // namespace gridfree::worker_cli
