// SPDX-License-Identifier: GPL-3.0-or-later
// The memory budget's source (sched/memory_budget.h).
#include "sched/memory_budget.h"

#include <fstream>
#include <iterator>
#include <sstream>

#include "core/input_error.h"
#include "job/memory_estimate.h"

namespace gridfree {

std::optional<double> mem_available_bytes(const std::string& text) {
  std::istringstream in(text);
  std::string key, unit;
  double value = 0;
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemAvailable:") {
      if (!(value > 0)) return std::nullopt;
      return unit.find("kB") != std::string::npos ? value * 1024.0 : value;
    }
  }
  return std::nullopt;
}

MemoryBudget resolve_memory_budget(const std::string& flag) {
  if (!flag.empty()) {
    const auto parsed = parse_memory_size(flag);
    if (!parsed) throw InputError("--memory-budget", "'" + flag.substr(0, 40) + "' is not a size like 8G or 512M");
    return {*parsed, "--memory-budget"};
  }
  std::ifstream in("/proc/meminfo");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (const auto avail = mem_available_bytes(text)) return {*avail, "MemAvailable"};
  return {static_cast<double>(machine_memory_bytes()), "physical memory"};
}

}  // namespace gridfree
