// SPDX-License-Identifier: GPL-3.0-or-later
// Ranked concerns of each series (see series_concerns.h).
#include "report/series_concerns.h"

#include <algorithm>
#include <map>

#include "extrap/value_format.h"
#include "report/stability_map.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {
namespace {

void add(SeriesConcerns& c, int weight, std::string text, std::string word) {
  c.weight = std::max(c.weight, weight);
  c.total += weight;
  c.concerns.push_back(std::move(text));
  c.words.push_back(std::move(word));
}

// "2 failed grids (1 diverged at Δ* 0.5, 1 stalled at Δ* 0.7861)".
std::string failed_grids_text(const SeriesSummary& s, bool& stalled) {
  std::vector<std::string> parts;
  for (const GridPoint& g : s.series.grids) {
    if (!is_failed(g)) continue;
    const std::string outcome = grid_outcome(g);
    stalled = stalled || outcome == "stalled";
    parts.push_back(outcome + " at " + cell_size_text(series_vocabulary(s.series), g.delta_star));
  }
  std::string out = std::to_string(s.failed) + " failed grid" + (s.failed == 1 ? "" : "s") + " (";
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + parts[i];
  return out + ")";
}

std::optional<double> concern_rde(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty()) return std::nullopt;
  return s.extrapolation->grids.front().rde;
}

}  // namespace

std::vector<SeriesConcerns> series_concerns(const std::vector<SeriesSummary>& series, double p_low, double p_high) {
  std::vector<SeriesConcerns> out;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const SeriesSummary& s = series[i];
    SeriesConcerns c;
    c.series = i;
    const bool has_f0 = s.f0().has_value();
    if (!has_f0 && !s.incomplete) add(c, 50, "no extrapolated value", "no-f0");
    if (s.verdict == "unreliable" || s.verdict == "insufficient_grids") add(c, 50, "verdict " + s.verdict, s.verdict);
    if (s.coverage && s.coverage->below_promise())
      add(c, 40, "coverage self-check missed: " + s.coverage->summary(), "coverage");
    if (s.failed > 0) {
      bool stalled = false;
      std::string text = failed_grids_text(s, stalled);
      add(c, 30, std::move(text), "failed");
      if (stalled) c.words.push_back("stalled");
    }
    if (s.verdict == "pre-asymptotic") add(c, 20, "verdict pre-asymptotic", "pre-asymptotic");
    if (s.extrapolation && s.extrapolation->p && !(*s.extrapolation->p >= p_low && *s.extrapolation->p <= p_high))
      add(c, 15,
          "order p = " + format_g(*s.extrapolation->p, 3) + " outside the declared range [" + format_g(p_low, 4) +
              ", " + format_g(p_high, 4) + "]",
          "order");
    if (c.weight > 0) out.push_back(std::move(c));
  }
  std::stable_sort(out.begin(), out.end(), [&](const SeriesConcerns& a, const SeriesConcerns& b) {
    if (a.weight != b.weight) return a.weight > b.weight;
    if (a.total != b.total) return a.total > b.total;
    const double ra = concern_rde(series[a.series]).value_or(-1), rb = concern_rde(series[b.series]).value_or(-1);
    return ra > rb;
  });
  return out;
}

}  // namespace gridfree
