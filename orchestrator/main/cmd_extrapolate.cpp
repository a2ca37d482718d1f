// gridfree extrapolate (placeholder until implemented).
#include <iostream>

#include "commands.h"
#include "core/exit_codes.h"

namespace gridfree::cli {

void add_extrapolate_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("extrapolate", "not implemented yet");
  sub->callback([&exit_code] {
    std::cerr << "error: 'extrapolate' is not implemented yet\n";
    exit_code = to_int(ExitCode::kInternalError);
  });
}

}  // namespace gridfree::cli
