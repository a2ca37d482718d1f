// SPDX-License-Identifier: GPL-3.0-or-later
// expand(): a Study → its series (the design) and one job per (series, grid).
//
// factorial:      every case × convection × fwhm_dp × drag × deposition
//                 (external: every case × the study's own factors' levels, × quantity);
// one_at_a_time:  the baseline, then each other case and each other level of
//                 each factor varied alone from it: 1 + Σ_f (levels_f − 1)
//                 series (cases count as a factor). No duplicates.
// Grids: cells = round(L*/Δ*) per direction (cells_for_delta_star) per case,
// or the explicit cells. Each job document is docs/INTERFACE.md §2's job with the
// study's numerics merged in, identified by job_hash.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "grid/grid.h"
#include "job/job_hash.h"
#include "study/study.h"
#include "study/study_alignment.h"
#include "study/study_transfer.h"

namespace gridfree {

namespace {

// Every combination of the external factors' levels, the first factor's
// level varying slowest (factors in name order, levels as listed).
std::vector<std::map<std::string, std::string>> level_combinations(const Study& s) {
  std::vector<std::map<std::string, std::string>> out = {{}};
  for (const auto& [name, levels] : s.factors.external) {
    std::vector<std::map<std::string, std::string>> next;
    for (const auto& partial : out)
      for (const auto& level : levels) {
        auto combined = partial;
        combined[name] = level;
        next.push_back(std::move(combined));
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace

std::vector<SeriesKey> external_configurations(const Study& s) {
  std::vector<SeriesKey> out;
  std::set<std::pair<std::string, std::map<std::string, std::string>>> seen;
  auto add = [&](const std::string& case_name, const std::map<std::string, std::string>& levels) {
    if (!seen.insert({case_name, levels}).second) return;
    SeriesKey k{case_name, "", 0, "", ""};
    k.levels = levels;
    out.push_back(std::move(k));
  };
  if (s.baseline) {  // one_at_a_time: the baseline, each other case, each other level alone
    const SeriesKey& b = *s.baseline;
    add(b.case_name, b.levels);
    for (const auto& c : s.cases) add(c.name, b.levels);
    for (const auto& [name, levels] : s.factors.external)
      for (const auto& level : levels) {
        auto varied = b.levels;
        varied[name] = level;
        add(b.case_name, varied);
      }
    return out;
  }
  for (const auto& c : s.cases)
    for (const auto& levels : level_combinations(s)) add(c.name, levels);
  return out;
}

std::vector<SeriesKey> design_series(const Study& s) {
  std::vector<SeriesKey> out;
  std::set<SeriesKey> seen;
  auto add = [&](const SeriesKey& k) {
    if (seen.insert(k).second) out.push_back(k);
  };
  const auto& f = s.factors;
  if (s.external()) {  // one series per (case × levels × quantity)
    for (const auto& config : external_configurations(s)) {
      const StudyCase* c = s.find_case(config.case_name);
      if (c == nullptr || !c->external) continue;
      for (const auto& q : c->external->quantities) {
        SeriesKey k{config.case_name, "", 0, "", ""};
        k.levels = config.levels;
        k.quantity = q.name;
        add(k);
      }
    }
    return out;
  }
  if (s.baseline) {
    const SeriesKey& b = *s.baseline;
    add(b);
    for (const auto& c : s.cases) {
      SeriesKey k = b;
      k.case_name = c.name;
      add(k);
    }
    for (const auto& v : f.convection) {
      SeriesKey k = b;
      k.convection = v;
      add(k);
    }
    for (double v : f.fwhm_dp) {
      SeriesKey k = b;
      k.fwhm_dp = v;
      add(k);
    }
    for (const auto& v : f.drag) {
      SeriesKey k = b;
      k.drag = v;
      add(k);
    }
    for (const auto& v : f.deposition) {
      SeriesKey k = b;
      k.deposition = v;
      add(k);
    }
    return out;
  }
  for (const auto& c : s.cases)
    for (const auto& conv : f.convection)
      for (double w : f.fwhm_dp)
        for (const auto& d : f.drag)
          for (const auto& dep : f.deposition) add(SeriesKey{c.name, conv, w, d, dep});
  return out;
}

std::vector<std::array<int, 3>> grids_for_case(const Study& s, const StudyCase& c) {
  if (!s.grid_cells.empty()) return s.grid_cells;
  std::vector<std::array<int, 3>> out;
  for (double ds : s.grid_delta_star) out.push_back(cells_for_delta_star(c.spec.domain_dp, ds));
  return out;
}

nlohmann::json make_job_document(const Study& s, const SeriesKey& key, const std::array<int, 3>& cells) {
  const StudyCase* c = s.find_case(key.case_name);
  nlohmann::json numerics = s.numerics.is_object() ? s.numerics : nlohmann::json::object();
  numerics["grid"] = {{"cells", {cells[0], cells[1], cells[2]}}};
  numerics["convection"] = key.convection;
  numerics["drag"] = key.drag;
  numerics["deposition"] = deposition_document(s, key.deposition, key.fwhm_dp);
  return {{"schema", "gridfree/job/1"},
          {"case", c != nullptr ? c->doc : nlohmann::json::object()},
          {"numerics", numerics}};
}

namespace {

// External cases: one job per (case × levels × grid), shared by that
// configuration's series (one per quantity); h from the case's expression.
void expand_external(const Study& s, ExpandedStudy& out) {
  using Configuration = std::pair<std::string, std::map<std::string, std::string>>;
  std::map<Configuration, std::vector<StudyJob>> jobs_of_config;
  for (const auto& config : external_configurations(s)) {
    const StudyCase* found = s.find_case(config.case_name);
    if (found == nullptr || !found->external) continue;
    const StudyCase& c = *found;
    auto& jobs = jobs_of_config[{c.name, config.levels}];
    const GridVariables& grids = external_grids_of(s, c.name);
    const auto ladder = s.external_ladders.find(c.name);
    for (std::size_t g = 0; g < external_grid_count(grids); ++g) {
      if (s.adaptive_grids && g >= AdaptiveGrids::kFirstGrids) break;  // the rest as decided (sched/adaptive_series.h)
      const ExternalGrid grid = external_grid(*c.external, grids, g);
      StudyJob job;
      job.grid = g;
      const double cells = grid.cells ? std::max(1.0, std::round(*grid.cells)) : 1.0;
      job.cells = {static_cast<int>(std::min(cells, 2.0e9)), 1, 1};
      job.delta_star = grid.h;
      job.delta_star_nominal = ladder != s.external_ladders.end() ? ladder->second.h_nominal.at(g) : grid.h;
      job.doc = external_job_document(*c.external, c.name, grid, g, config.levels);
      job.hash = job_hash(job.doc);
      jobs.push_back(std::move(job));
    }
  }
  for (std::size_t si = 0; si < out.series.size(); ++si) {
    out.transfer.emplace_back();
    for (StudyJob job : jobs_of_config[{out.series[si].case_name, out.series[si].levels}]) {
      job.series = si;
      out.jobs.push_back(std::move(job));
    }
  }
}

}  // namespace

std::size_t distinct_job_count(const ExpandedStudy& ex) {
  std::set<std::string> hashes;
  for (const auto& j : ex.jobs) hashes.insert(j.hash);
  return hashes.size();
}

ExpandedStudy expand(const Study& s) {
  ExpandedStudy out;
  out.series = design_series(s);
  if (s.external()) {
    expand_external(s, out);
    return out;
  }
  for (std::size_t si = 0; si < out.series.size(); ++si) {
    const auto& key = out.series[si];
    const StudyCase* c = s.find_case(key.case_name);
    if (c == nullptr) {
      out.transfer.emplace_back();
      continue;
    }
    out.transfer.push_back(transfer_columns(deposition_document(s, key.deposition, key.fwhm_dp)));
    const auto grids = grids_for_case(s, *c);
    std::set<std::string> hashes;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      if (s.adaptive_grids && g >= AdaptiveGrids::kFirstGrids) break;  // the rest as decided (sched/adaptive_series.h)
      StudyJob job;
      job.series = si;
      job.grid = g;
      job.cells = grids[g];
      job.delta_star = delta_star_of(c->spec.domain_dp, grids[g]);
      if (!s.grid_delta_star.empty()) job.delta_star_nominal = s.grid_delta_star[g];
      job.doc = make_job_document(s, key, grids[g]);
      job.hash = job_hash(job.doc);
      if (hashes.insert(job.hash).second) out.jobs.push_back(std::move(job));
    }
  }
  expand_alignment(s, out);  // re-aligned variants, when the study asks (study_alignment.cpp)
  return out;
}

}  // namespace gridfree
