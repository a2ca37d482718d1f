// SPDX-License-Identifier: GPL-3.0-or-later
// How many OpenMP threads a worker command uses: `--threads N` when given;
// otherwise OMP_NUM_THREADS when set (libgomp has read it already);
// otherwise every core.
#pragma once

namespace gridfree::worker_cli {

// `requested` = the --threads value, 0 when absent; negative is refused
// (InputError naming --threads). Sets the OpenMP default and returns it.
int use_thread_count(int requested);

}  // namespace gridfree::worker_cli
