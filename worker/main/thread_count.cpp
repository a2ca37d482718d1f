// SPDX-License-Identifier: GPL-3.0-or-later
#include "thread_count.h"

#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "core/input_error.h"

namespace gridfree::worker_cli {

int use_thread_count(int requested) {
  if (requested < 0) throw InputError("--threads", "must be a positive number of threads");
  if (requested > 0) {
    omp_set_num_threads(requested);
  } else if (std::getenv("OMP_NUM_THREADS") == nullptr) {
    omp_set_num_threads(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  }
  return omp_get_max_threads();
}

}  // namespace gridfree::worker_cli
