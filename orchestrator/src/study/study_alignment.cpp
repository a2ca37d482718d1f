// SPDX-License-Identifier: GPL-3.0-or-later
// The alignment check as a study option (study_alignment.h).
#include "study/study_alignment.h"

#include <algorithm>
#include <set>

#include "grid/grid.h"
#include "job/job_hash.h"

namespace gridfree {
namespace {

using nlohmann::json;

constexpr std::array<const char*, 3> kOffsetFields{"nx_offsets", "ny_offsets", "nz_offsets"};
constexpr int kMaxOffset = 1000;

std::vector<int> read_offsets(const json& a, const std::string& at, ProblemList& problems) {
  std::vector<int> out;
  if (!a.is_array() || a.empty()) {
    problems.add(at, "must be a non-empty array of integers (cells added to the grid's count)");
    return out;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string where = at + "/" + std::to_string(i);
    if (!a[i].is_number_integer() || std::abs(a[i].get<long long>()) > kMaxOffset) {
      problems.add(where, "must be an integer from -1000 to 1000");
      continue;
    }
    const int v = a[i].get<int>();
    if (std::find(out.begin(), out.end(), v) != out.end()) {
      problems.add(where, "offset listed twice");
      continue;
    }
    out.push_back(v);
  }
  return out;
}

// Indices of the listed grids in the study's own list.
void read_grids(const json& a, const Study& s, AlignmentOption& opt, ProblemList& problems) {
  const bool by_ds = a.contains("delta_star"), by_cells = a.contains("cells");
  if (by_ds && by_cells) {
    problems.add("/alignment", "give at most one of delta_star and cells");
    return;
  }
  const std::size_t n = s.grid_delta_star.empty() ? s.grid_cells.size() : s.grid_delta_star.size();
  if (!by_ds && !by_cells) {
    for (std::size_t g = 0; g < n; ++g) opt.grids.push_back(g);
    return;
  }
  const std::string key = by_ds ? "delta_star" : "cells";
  const std::string at = "/alignment/" + key;
  if (by_ds != !s.grid_delta_star.empty()) {
    problems.add(at, "the study's grids are given as " + std::string(by_ds ? "cells" : "delta_star") +
                         "; list the grids to check the same way");
    return;
  }
  const json& list = a[key];
  if (!list.is_array() || list.empty()) {
    problems.add(at, "must be a non-empty array of the study's grids");
    return;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    std::optional<std::size_t> found;
    for (std::size_t g = 0; g < n && !found; ++g) {
      if (by_ds && list[i].is_number() && list[i].get<double>() == s.grid_delta_star[g]) found = g;
      if (by_cells && list[i].is_array() && list[i].size() == 3 && list[i].get<std::vector<int>>() ==
                                                                       std::vector<int>(s.grid_cells[g].begin(), s.grid_cells[g].end()))
        found = g;
    }
    if (!found) {
      problems.add(at + "/" + std::to_string(i), "is not one of the study's grids (/grids/" + key + ")");
      continue;
    }
    if (std::find(opt.grids.begin(), opt.grids.end(), *found) != opt.grids.end()) {
      problems.add(at + "/" + std::to_string(i), "grid listed twice");
      continue;
    }
    opt.grids.push_back(*found);
  }
}

}  // namespace

std::vector<std::array<int, 3>> alignment_offsets(const AlignmentOption& opt) {
  auto or_zero = [](const std::vector<int>& v) { return v.empty() ? std::vector<int>{0} : v; };
  std::vector<std::array<int, 3>> out;
  for (int y : or_zero(opt.offsets[1]))
    for (int x : or_zero(opt.offsets[0]))
      for (int z : or_zero(opt.offsets[2]))
        if (x != 0 || y != 0 || z != 0) out.push_back({x, y, z});
  return out;
}

void parse_alignment(const json& doc, Study& s, ProblemList& problems) {
  auto a = doc.find("alignment");
  if (a == doc.end()) return;
  if (!a->is_object()) {
    problems.add("/alignment", "must be an object");
    return;
  }
  AlignmentOption opt;
  for (int axis = 0; axis < 3; ++axis)
    if (auto o = a->find(kOffsetFields[axis]); o != a->end())
      opt.offsets[axis] = read_offsets(*o, std::string("/alignment/") + kOffsetFields[axis], problems);
  read_grids(*a, s, opt, problems);
  if (alignment_offsets(opt).empty())
    problems.add("/alignment", "needs a non-zero offset in nx_offsets, ny_offsets or nz_offsets");
  // Every variant of every case must still be a grid the worker accepts.
  for (const auto& c : s.cases) {
    const auto grids = grids_for_case(s, c);
    for (std::size_t g : opt.grids) {
      if (g >= grids.size()) continue;
      for (const auto& off : alignment_offsets(opt))
        for (int axis = 0; axis < 3; ++axis) {
          const int n = grids[g][axis] + off[axis];
          if (n < 1 || n > kMaxCellsPerAxis)
            problems.add(std::string("/alignment/") + kOffsetFields[axis],
                         "offset " + std::to_string(off[axis]) + " gives " + std::to_string(n) +
                             " cells on grid " + std::to_string(g) + " of case " + c.name + " (1 to " +
                             std::to_string(kMaxCellsPerAxis) + " allowed)");
        }
    }
  }
  s.alignment = opt;
}

void expand_alignment(const Study& s, ExpandedStudy& out) {
  if (!s.alignment) return;
  const auto offsets = alignment_offsets(*s.alignment);
  for (std::size_t si = 0; si < out.series.size(); ++si) {
    const SeriesKey& key = out.series[si];
    const StudyCase* c = s.find_case(key.case_name);
    if (c == nullptr) continue;
    const auto grids = grids_for_case(s, *c);
    for (std::size_t g : s.alignment->grids) {
      const std::string base_hash = job_hash(make_job_document(s, key, grids[g]));
      std::set<std::string> seen{base_hash};
      for (const auto& off : offsets) {
        AlignmentJob job;
        job.series = si;
        job.grid = g;
        job.offsets = off;
        for (int a = 0; a < 3; ++a) job.cells[a] = grids[g][a] + off[a];
        job.delta_star = delta_star_of(c->spec.domain_dp, job.cells);
        job.doc = make_job_document(s, key, job.cells);
        job.hash = job_hash(job.doc);
        job.base_hash = base_hash;
        if (seen.insert(job.hash).second) out.alignment.push_back(std::move(job));
      }
    }
  }
}

}  // namespace gridfree
