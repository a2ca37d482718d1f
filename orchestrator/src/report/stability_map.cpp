// SPDX-License-Identifier: GPL-3.0-or-later
// The stability map's data (stability_map.h).
#include "report/stability_map.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "extrap/value_format.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

bool stab_starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// The column of a grid: its Δ* to 3 significant digits, so grids of one
// nominal Δ* in domains of different sizes share a column.
double stability_column_of(double delta_star) { return std::stod(format_cell_size(delta_star)); }


// What a failure says in a line: the outcome word and the worker's reason.
std::string stability_failure_text(const GridPoint& g, const std::string& outcome) {
  std::string why = g.reason.empty() ? "(no reason recorded)" : g.reason;
  if (why.size() > 240) why = why.substr(0, 237) + "...";
  return outcome + " (" + why + ")";
}

}  // namespace

std::string grid_outcome(const std::string& status, const std::string& reason, const std::string& worker_outcome) {
  if (status == "converged") return "converged";
  if (status == "not_converged") {
    if (worker_outcome == "stalled" || worker_outcome == "iteration_cap") return worker_outcome;
    return reason.find("stalling for") != std::string::npos ? "stalled" : "iteration_cap";
  }
  if (status == "diverged" || status == "invalid") return status;
  if (status == "failed") return stab_starts_with(reason, "timed out") ? "timed_out" : "failed";
  if (status == "cancelled") return "cancelled";
  return "pending";  // queued | running
}

std::string grid_outcome(const GridPoint& g) { return grid_outcome(g.status, g.reason, g.worker_outcome); }

bool is_failure_outcome(const std::string& o) {
  return o == "stalled" || o == "iteration_cap" || o == "diverged" || o == "invalid" || o == "timed_out" ||
         o == "failed";
}

std::string stability_line(const SeriesSummary& s) {
  std::vector<const GridPoint*> grids;  // coarsest first
  for (const GridPoint& g : s.series.grids) grids.push_back(&g);
  std::sort(grids.begin(), grids.end(), [](const auto* a, const auto* b) { return a->delta_star > b->delta_star; });
  const GridPoint* last_ok = nullptr;
  const GridPoint* first_bad = nullptr;
  int failures = 0, pending = 0, later_ok = 0;
  for (const GridPoint* g : grids) {
    const std::string o = grid_outcome(*g);
    if (o == "pending" || o == "cancelled") {
      ++pending;
      continue;
    }
    if (is_failure_outcome(o)) {
      ++failures;
      if (!first_bad) first_bad = g;
    } else if (!first_bad) {
      last_ok = g;
    } else {
      ++later_ok;
    }
  }
  std::string line;
  // "Δ* 0.5", or an external series' "h 0.005" (its declared h).
  const CaseVocabulary words = series_vocabulary(s.series);
  const auto at = [&words](double h) { return cell_size_text(words, h); };
  if (!first_bad && !last_ok) return pending ? "no grid finished yet" : "no grids";
  if (!first_bad) {
    line = "solved on every finished grid, down to " + at(last_ok->delta_star);
  } else {
    const std::string why = stability_failure_text(*first_bad, grid_outcome(*first_bad));
    line = last_ok ? "solved down to " + at(last_ok->delta_star) + "; first failure at " +
                         at(first_bad->delta_star) + ": " + why
                   : "fails from the coarsest grid: first failure at " + at(first_bad->delta_star) + ": " +
                         why;
    if (failures > 1) line += "; " + std::to_string(failures) + " failed grids in all";
    if (later_ok > 0) line += "; " + std::to_string(later_ok) + " finer grid(s) solved again";
  }
  if (pending) line += " (" + std::to_string(pending) + " grid(s) not finished)";
  return line;
}

std::string gci_usability(const GciView& g, double p_low, double p_high) {
  if (g.convergence == "divergent" || g.convergence == "oscillatory") return g.convergence;
  if (g.status != "ok" || !g.p || !g.f_ext) return "no p";
  if (!(*g.p >= p_low && *g.p <= p_high)) return "p outside [" + format_g(p_low, 4) + ", " + format_g(p_high, 4) + "]";
  return "usable";
}

MethodTally method_tally(const SeriesSummary& s, double p_low, double p_high) {
  MethodTally t;
  if (s.extrapolation) {
    for (const GciView& g : s.extrapolation->gci) {
      ++t.triplets;
      const std::string use = gci_usability(g, p_low, p_high);
      if (use == "divergent") ++t.divergent;
      else if (use == "oscillatory") ++t.oscillatory;
      else if (use == "no p") ++t.no_number;
      else if (use != "usable") ++t.p_out_of_range;
      else ++t.gci_usable;
    }
    t.least_squares_usable = s.extrapolation->f0.has_value() && s.extrapolation->status == "ok";
    t.least_squares = t.least_squares_usable ? "f0 by " + s.extrapolation->method
                                             : "no f0 (" + s.extrapolation->status + ")";
  } else {
    t.least_squares = s.extrapolation_error.empty() ? "no extrapolation" : "no f0 (" + s.extrapolation_error + ")";
  }
  return t;
}

StabilityMap stability_map(const std::vector<SeriesSummary>& series, double p_low, double p_high,
                           std::size_t max_rows) {
  StabilityMap m;
  m.words = study_vocabulary(series);
  for (const auto& s : series)
    for (const GridPoint& g : s.series.grids) m.columns.push_back(stability_column_of(g.delta_star));
  std::sort(m.columns.begin(), m.columns.end(), std::greater<>());
  m.columns.erase(std::unique(m.columns.begin(), m.columns.end()), m.columns.end());

  std::vector<StabilityRow> rows;
  for (const auto& s : series) {
    StabilityRow r;
    r.label = s.label;
    r.cells.resize(m.columns.size());
    for (const GridPoint& g : s.series.grids) {
      const auto col = std::find(m.columns.begin(), m.columns.end(), stability_column_of(g.delta_star)) - m.columns.begin();
      StabilityCell& c = r.cells[static_cast<std::size_t>(col)];
      c.present = true;
      c.outcome = grid_outcome(g);
      c.iterations = g.iterations;
      c.delta_star = g.delta_star;
      c.reason = g.reason;
      c.remedy_from = g.remedy_from_iteration;
      if (is_failure_outcome(c.outcome)) ++r.failures;
      else if (c.outcome == "converged") ++r.converged;
      else ++r.pending;
    }
    r.line = stability_line(s);
    r.methods = method_tally(s, p_low, p_high);
    rows.push_back(std::move(r));
  }
  m.series_total = static_cast<int>(rows.size());
  m.series_with_failures =
      static_cast<int>(std::count_if(rows.begin(), rows.end(), [](const StabilityRow& r) { return r.failures > 0; }));
  std::stable_sort(rows.begin(), rows.end(),
                   [](const StabilityRow& a, const StabilityRow& b) { return a.failures > b.failures; });
  if (rows.size() > max_rows) {
    m.omitted = static_cast<int>(rows.size() - max_rows);
    rows.resize(max_rows);
  }
  m.rows = std::move(rows);
  return m;
}

}  // namespace gridfree
