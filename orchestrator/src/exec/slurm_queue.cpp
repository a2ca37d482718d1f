// squeue output parsing (see slurm_queue.h).
#include "exec/slurm_queue.h"

#include <cstdlib>
#include <sstream>

namespace gridfree {

std::vector<std::string> squeue_command() { return {"squeue", "--me", "-h", "-r", "-o", "%i|%T|%r|%M"}; }

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

std::map<std::string, QueueEntry> parse_squeue(const std::string& text) {
  std::map<std::string, QueueEntry> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, '|');) f.push_back(x);
    if (f.size() != 4 || f[0].empty()) continue;
    QueueEntry e{f[1], f[2], parse_slurm_duration(f[3]).value_or(0)};
    out[f[0]] = e;
  }
  return out;
}

}  // namespace gridfree
