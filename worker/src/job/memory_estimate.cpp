// SPDX-License-Identifier: GPL-3.0-or-later
// The worker's memory guard (job/memory_estimate.h).
#include "job/memory_estimate.h"

#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace gridfree {

double job_memory_estimate_bytes(const std::array<int, 3>& cells) {
  return kWorkerBytesPerCell * static_cast<double>(cells[0]) * cells[1] * cells[2] + kWorkerBaseBytes;
}

std::uint64_t machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
}

std::optional<double> parse_memory_size(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || !(value > 0) || !std::isfinite(value)) return std::nullopt;
  std::string unit(end, text.data() + text.size());
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() >= 2 && unit.substr(unit.size() - 2) == "IB") unit.resize(unit.size() - 2);
  else if (!unit.empty() && unit.back() == 'B') unit.pop_back();
  const std::string units = "KMGT";
  double scale = 1;
  if (unit.size() == 1 && units.find(unit[0]) != std::string::npos)
    scale = std::pow(1024.0, static_cast<double>(units.find(unit[0]) + 1));
  else if (!unit.empty())
    return std::nullopt;
  return value * scale;
}

std::string memory_text(double bytes) {
  char buffer[32];
  if (bytes >= 1024.0 * 1024 * 1024) std::snprintf(buffer, sizeof buffer, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else std::snprintf(buffer, sizeof buffer, "%.0f MiB", bytes / (1024.0 * 1024));
  return buffer;
}

}  // namespace gridfree
