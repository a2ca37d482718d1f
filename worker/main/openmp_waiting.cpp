#include "openmp_waiting.h"

#include <unistd.h>

#include <cstdlib>

namespace gridfree::worker_cli {

void use_default_openmp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (::setenv(kWaitVariable, kWaitDefault, 0) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Only reached when the exec failed: run on with libgomp's default.
}

}  // namespace gridfree::worker_cli
