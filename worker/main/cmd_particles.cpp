// gridfree-worker particles (placeholder until implemented).
#include <iostream>

#include "commands.h"
#include "core/exit_codes.h"

namespace gridfree::worker_cli {

void add_particles_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("particles", "not implemented yet");
  sub->callback([&exit_code] {
    std::cerr << "error: 'particles' is not implemented yet\n";
    exit_code = to_int(ExitCode::kInternalError);
  });
}

}  // namespace gridfree::worker_cli
