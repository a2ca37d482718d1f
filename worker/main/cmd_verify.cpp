// gridfree-worker verify (placeholder until implemented).
#include <iostream>

#include "commands.h"
#include "core/exit_codes.h"

namespace gridfree::worker_cli {

void add_verify_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("verify", "not implemented yet");
  sub->callback([&exit_code] {
    std::cerr << "error: 'verify' is not implemented yet\n";
    exit_code = to_int(ExitCode::kInternalError);
  });
}

}  // namespace gridfree::worker_cli
