// gridfree validate|plan|run|submit|daemon|status|report|cancel (placeholder until implemented).
#include "commands.h"

namespace gridfree::cli {

void add_study_commands(CLI::App&, int&) {}

}  // namespace gridfree::cli
