// SPDX-License-Identifier: GPL-3.0-or-later
// Programs on a PATH value (see program_path.h).
#include "exec/program_path.h"

#include <unistd.h>

namespace gridfree {

std::optional<std::filesystem::path> find_on_path(const std::string& program, const std::string& path) {
  std::size_t start = 0;
  for (;;) {
    const auto end = path.find(':', start);
    const std::string dir = path.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::filesystem::path candidate = (dir.empty() ? std::filesystem::path(".") : std::filesystem::path(dir)) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) return std::nullopt;
    start = end + 1;
  }
}

std::vector<std::string> missing_programs(const std::vector<std::string>& programs, const std::string& path) {
  std::vector<std::string> out;
  for (const auto& p : programs)
    if (!find_on_path(p, path)) out.push_back(p);
  return out;
}

}  // namespace gridfree
