// SPDX-License-Identifier: GPL-3.0-or-later
// OpenMP threads that wait without stealing a shared core.
//
// By default libgomp lets an idle thread spin for a long time at every
// barrier before it sleeps. On a machine whose cores are busy with other
// work, the spinning thread takes the core that the thread it waits for
// needs, and two threads cost several times the CPU of one (docs/BENCHMARKS.md,
// "Waiting policy"). libgomp reads OMP_WAIT_POLICY and GOMP_SPINCOUNT once,
// when it is loaded — before main — so setting them in main is too late:
// the worker sets the default and executes itself again.
#pragma once

namespace gridfree::worker_cli {

// The environment variable and value the worker uses when the user has set
// neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT.
inline constexpr const char* kWaitVariable = "OMP_WAIT_POLICY";
inline constexpr const char* kWaitDefault = "passive";

// If neither variable is set: sets the default and replaces the process by
// a fresh copy of this executable with the same arguments (returns only if
// that fails, leaving libgomp's default). Otherwise does nothing.
void use_default_openmp_waiting(char** argv);

}  // namespace gridfree::worker_cli
