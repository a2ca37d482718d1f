// SPDX-License-Identifier: GPL-3.0-or-later
// Per-series digest and extrapolation call (see series_summary.h).
#include "report/series_summary.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <spdlog/spdlog.h>

#include "extrap/verdict.h"
#include "report/series_coverage.h"

namespace gridfree {

bool is_converged(const GridPoint& grid) {
  return grid.status == "converged" && grid.dp_star.has_value() && std::isfinite(*grid.dp_star);
}

bool is_pending(const GridPoint& grid) {
  return grid.status == "queued" || grid.status == "running" || grid.status.empty();
}

bool is_failed(const GridPoint& grid) { return !is_converged(grid) && !is_pending(grid); }

std::optional<double> SeriesSummary::f0() const {
  if (!extrapolation || !extrapolation->f0 || !std::isfinite(*extrapolation->f0)) return std::nullopt;
  return extrapolation->f0;
}

std::optional<double> SeriesSummary::relative_error(double f) const {
  const auto f_zero = f0();
  if (!f_zero || *f_zero == 0) return std::nullopt;
  return std::abs(f - *f_zero) / std::abs(*f_zero);
}

const ExtrapolatedGrid* SeriesSummary::extrapolated(const GridPoint& grid) const {
  return extrapolation && is_converged(grid) ? extrapolation->grid_at(grid.delta_star) : nullptr;
}

std::string SeriesSummary::note() const {
  std::string out;
  if (insufficient()) {
    // "solved" for grids (the solver converged), "converged" for verdicts.
    out = "insufficient grids (" + std::to_string(converged()) + " solved, " +
          std::to_string(kMinGridsForUncertainty) + " needed): no uncertainty";
  }
  if (incomplete) {
    if (!out.empty()) out += "; ";
    out += "incomplete (" + std::to_string(pending) + " of " + std::to_string(series.grids.size()) +
           " grids pending)";
  }
  if (!extrapolation_error.empty()) {
    if (!out.empty()) out += "; ";
    out += "extrapolation: " + extrapolation_error;
  }
  return out;
}

std::vector<SeriesSummary> summarize_series(const StudyReportData& data, const Extrapolator& extrapolate) {
  std::vector<SeriesSummary> out;
  out.reserve(data.series.size());
  for (const SeriesData& series : data.series) {
    SeriesSummary s;
    s.series = series;
    s.label = series.label();
    std::stable_sort(s.series.grids.begin(), s.series.grids.end(),
                     [](const GridPoint& a, const GridPoint& b) { return a.delta_star < b.delta_star; });
    for (const GridPoint& g : s.series.grids) {
      if (is_converged(g)) {
        s.h.push_back(g.delta_star);
        s.f.push_back(*g.dp_star);
      } else if (is_pending(g)) {
        ++s.pending;
      } else {
        ++s.failed;
      }
    }
    s.incomplete = s.pending > 0 || series.status == "queued" || series.status == "running";
    if (s.h.empty()) {
      s.extrapolation_error = "no converged grid";
    } else if (extrapolate) {
      try {
        s.extrapolation = from_json(extrapolate(s.h, s.f));
        const std::string& st = s.extrapolation->status;
        if (st != "ok" && st != "insufficient_grids" && !s.f0()) {
          s.extrapolation_error = st.empty() ? "no result" : st;
        }
      } catch (const std::exception& e) {
        spdlog::warn("report: extrapolation of series {} failed: {}", s.label, e.what());
        s.extrapolation.reset();
        s.extrapolation_error = e.what();
      }
    }
    if (s.extrapolation && !s.extrapolation->verdict.empty()) {
      s.verdict = s.extrapolation->verdict;
      s.verdict_reasons = s.extrapolation->verdict_reasons;
    } else {
      const Verdict v = verdict_without_fit(
          s.converged(), s.extrapolation ? "the extrapolation gave no verdict" : "no extrapolation: " + s.extrapolation_error);
      s.verdict = v.value;
      s.verdict_reasons = v.reasons;
    }
    if (s.incomplete) s.verdict_reasons.insert(s.verdict_reasons.begin(), "provisional: grids are still pending");
    s.coverage = series_coverage(s, extrapolate);
    s.series.stored_coverage.reset();  // now in s.coverage: one copy per series
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace gridfree
