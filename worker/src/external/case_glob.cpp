// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/case_glob.h"

#include <fnmatch.h>

#include <algorithm>
#include <system_error>
#include <vector>

namespace gridfree {
namespace {

std::vector<std::string> glob_parts(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    if (end > start && path.compare(start, end - start, ".") != 0) parts.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  return parts;
}

bool glob_parts_match(const std::vector<std::string>& pat, std::size_t i, const std::vector<std::string>& path,
                      std::size_t j) {
  if (i == pat.size()) return j == path.size();
  if (pat[i] == "**") {
    for (std::size_t k = j; k <= path.size(); ++k)
      if (glob_parts_match(pat, i + 1, path, k)) return true;
    return false;
  }
  if (j == path.size()) return false;
  return ::fnmatch(pat[i].c_str(), path[j].c_str(), FNM_PERIOD) == 0 && glob_parts_match(pat, i + 1, path, j + 1);
}

bool has_wildcard(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

}  // namespace

bool case_glob_match(const std::string& pattern, const std::string& relative_path) {
  return glob_parts_match(glob_parts(pattern), 0, glob_parts(relative_path), 0);
}

std::optional<std::filesystem::path> newest_case_match(const std::filesystem::path& root, const std::string& pattern) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto parts = glob_parts(pattern);
  // The literal folders before the first wildcard: where the walk starts.
  fs::path base = root;
  std::size_t literal = 0;
  while (literal + 1 < parts.size() && !has_wildcard(parts[literal])) base /= parts[literal++];
  if (!has_wildcard(pattern)) {
    const fs::path p = root / pattern;
    if (fs::is_regular_file(p, ec)) return p;
    return std::nullopt;
  }
  std::optional<fs::path> best;
  fs::file_time_type best_time{};
  if (!fs::is_directory(base, ec)) return std::nullopt;
  for (fs::recursive_directory_iterator it(base, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string rel = it->path().lexically_relative(root).generic_string();
    if (!case_glob_match(pattern, rel)) continue;
    const auto t = it->last_write_time(ec);
    if (!best || t > best_time || (t == best_time && it->path() > *best)) {
      best = it->path();
      best_time = t;
    }
  }
  return best;
}

}  // namespace gridfree
