// SPDX-License-Identifier: GPL-3.0-or-later
// SIGTERM / SIGINT to the worker: a request to stop after the current outer
// iteration (and write a checkpoint when asked to; docs/INTERFACE.md §2).
// The handler only sets a flag — the one piece of process-wide state, as
// signal handlers require — that the solve polls.
#pragma once

namespace gridfree::worker_cli {

void install_stop_handlers();
bool stop_requested();

}  // namespace gridfree::worker_cli
