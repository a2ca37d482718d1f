// SPDX-License-Identifier: GPL-3.0-or-later
// Dropping repeated and follow-on problems (core/follow_on_problems.h).
#include "core/follow_on_problems.h"

#include <set>
#include <string>

namespace gridfree {
namespace {

// Whether `reason` says the value at its pointer could not be read at all.
bool unreadable(const std::string& reason) {
  return reason.rfind("expected ", 0) == 0 || reason.rfind("required, but missing", 0) == 0;
}

// Whether a value that contains the one at `pointer` is in `unreadable_at`
// (its ancestors: "/a/b/c" -> "/a/b", "/a", ""). Cost: the pointer's depth.
bool inside_any(const std::string& pointer, const std::set<std::string>& unreadable_at) {
  for (auto cut = pointer.rfind('/'); cut != std::string::npos && cut > 0; cut = pointer.rfind('/', cut - 1))
    if (unreadable_at.count(pointer.substr(0, cut)) > 0) return true;
  return !pointer.empty() && pointer[0] == '/' && unreadable_at.count("") > 0;
}

}  // namespace

std::vector<Problem> without_follow_ons(const std::vector<Problem>& problems) {
  std::vector<Problem> kept;
  std::set<std::string> reported, unreadable_at;
  for (const auto& p : problems)
    if (unreadable(p.reason)) unreadable_at.insert(p.where);
  for (const auto& p : problems) {
    if (reported.count(p.where) > 0 || inside_any(p.where, unreadable_at)) continue;
    reported.insert(p.where);
    kept.push_back(p);
  }
  return kept;
}

}  // namespace gridfree
