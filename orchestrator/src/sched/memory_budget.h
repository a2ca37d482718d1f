// SPDX-License-Identifier: GPL-3.0-or-later
// The memory budget of a local `run`/`daemon` (sched/budget.h):
// --memory-budget SIZE when given, else this machine's MemAvailable
// (/proc/meminfo) when the scheduler starts, else its physical memory.
#pragma once

#include <optional>
#include <string>

namespace gridfree {

struct MemoryBudget {
  double bytes = 0;    // 0 = none
  std::string source;  // "--memory-budget", "MemAvailable", "physical memory"
};

// MemAvailable from a /proc/meminfo text ("MemAvailable:  123456 kB"), bytes.
std::optional<double> mem_available_bytes(const std::string& meminfo_text);

// Throws InputError naming --memory-budget when `flag` is not a size.
MemoryBudget resolve_memory_budget(const std::string& flag);

}  // namespace gridfree
