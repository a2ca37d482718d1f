// SPDX-License-Identifier: GPL-3.0-or-later
// squeue output parsing (see slurm_queue.h).
#include "exec/slurm_queue.h"

#include <charconv>
#include <cstdlib>
#include <sstream>
#include <string_view>

namespace gridfree {
namespace {

// "3-9,11,13-30" → the ranges; false if malformed.
bool parse_index_ranges(std::string_view text, std::vector<std::pair<long, long>>& out) {
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string_view part = text.substr(0, comma);
    text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    const auto dash = part.find('-');
    const std::string_view a = part.substr(0, dash);
    const std::string_view b = dash == std::string_view::npos ? a : part.substr(dash + 1);
    long first = 0, last = 0;
    const auto ra = std::from_chars(a.data(), a.data() + a.size(), first);
    const auto rb = std::from_chars(b.data(), b.data() + b.size(), last);
    if (a.empty() || b.empty() || ra.ptr != a.data() + a.size() || rb.ptr != b.data() + b.size() || last < first)
      return false;
    out.emplace_back(first, last);
  }
  return !out.empty();
}

}  // namespace

std::vector<std::string> squeue_command() { return {"squeue", "--me", "-h", "-o", "%i|%T|%r|%M"}; }

std::optional<double> parse_slurm_duration(const std::string& t) {
  if (t.empty()) return std::nullopt;
  double days = 0;
  std::string rest = t;
  if (const auto dash = t.find('-'); dash != std::string::npos) {
    char* end = nullptr;
    days = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + dash) return std::nullopt;
    rest = t.substr(dash + 1);
  }
  std::vector<double> parts;
  std::istringstream in(rest);
  for (std::string p; std::getline(in, p, ':');) {
    if (p.empty() || p.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    parts.push_back(std::strtod(p.c_str(), nullptr));
  }
  if (parts.empty() || parts.size() > 3) return std::nullopt;
  double s = 0;
  for (double v : parts) s = s * 60 + v;
  if (parts.size() == 1) s = parts[0];  // a bare number: seconds
  return days * 86400 + s;
}

const QueueEntry* QueueListing::find(const std::string& id) const {
  if (auto it = single_.find(id); it != single_.end()) return &it->second;
  const auto bar = id.rfind('_');
  if (bar == std::string::npos) return nullptr;
  auto r = ranges_.find(id.substr(0, bar));
  if (r == ranges_.end()) return nullptr;
  long index = 0;
  const char* begin = id.data() + bar + 1;
  const char* end = id.data() + id.size();
  const auto [ptr, ec] = std::from_chars(begin, end, index);
  if (ec != std::errc() || ptr != end || begin == end) return nullptr;
  for (const Range& x : r->second)
    if (index >= x.first && index <= x.last) return &combined_[x.entry];
  return nullptr;
}

QueueListing parse_squeue(const std::string& text) {
  QueueListing out;
  std::string_view rest(text);
  while (!rest.empty()) {
    const auto nl = rest.find('\n');
    const std::string_view line = rest.substr(0, nl);
    rest = nl == std::string_view::npos ? std::string_view() : rest.substr(nl + 1);
    std::string_view f[4];
    std::size_t n = 0, start = 0;
    for (;;) {
      const auto bar = line.find('|', start);
      if (n < 4) f[n] = line.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start);
      ++n;
      if (bar == std::string_view::npos) break;
      start = bar + 1;
    }
    if (n != 4 || f[0].empty()) continue;
    QueueEntry e{std::string(f[1]), std::string(f[2]), parse_slurm_duration(std::string(f[3])).value_or(0)};
    const std::string_view id = f[0];
    const auto open = id.find("_[");
    if (open == std::string_view::npos) {
      out.single_[std::string(id)] = std::move(e);
      ++out.lines_;
      continue;
    }
    // Combined pending tasks: "<array id>_[<ranges>[%<throttle>]]".
    if (id.back() != ']') continue;
    std::string_view inside = id.substr(open + 2, id.size() - open - 3);
    inside = inside.substr(0, inside.find('%'));
    std::vector<std::pair<long, long>> ranges;
    if (!parse_index_ranges(inside, ranges)) continue;
    out.combined_.push_back(std::move(e));
    auto& list = out.ranges_[std::string(id.substr(0, open))];
    for (const auto& [first, last] : ranges) list.push_back({first, last, out.combined_.size() - 1});
    ++out.lines_;
  }
  return out;
}

}  // namespace gridfree
