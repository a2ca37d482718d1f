// SPDX-License-Identifier: GPL-3.0-or-later
// Verdict counts and the worst series (see verdict_counts.h).
#include "report/verdict_counts.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>

#include "report/differences.h"
#include "report/report_layout.h"

namespace gridfree {

namespace {

std::vector<std::string> verdict_words(const std::vector<SeriesSummary>& series) {
  std::vector<std::string> words = {"converged", "pre-asymptotic", "unreliable", "insufficient_grids"};
  for (const auto& s : series) {
    const std::string w = s.verdict.empty() ? "no verdict" : s.verdict;
    if (std::find(words.begin(), words.end(), w) == words.end()) words.push_back(w);
  }
  return words;
}

struct Tally {
  int series = 0, incomplete = 0;
  std::map<std::string, int> by_verdict;
  void add(const SeriesSummary& s) {
    ++series;
    incomplete += s.incomplete ? 1 : 0;
    ++by_verdict[s.verdict.empty() ? "no verdict" : s.verdict];
  }
};

std::vector<Cell> tally_row(const std::string& factor, const std::string& level, const Tally& t,
                            const std::vector<std::string>& words) {
  std::vector<Cell> row = {text_cell(factor), text_cell(level), integer_cell(t.series)};
  for (const auto& w : words) {
    const auto it = t.by_verdict.find(w);
    row.push_back(integer_cell(it == t.by_verdict.end() ? 0 : it->second));
  }
  row.push_back(integer_cell(t.incomplete));
  return row;
}

int verdict_rank(const std::string& verdict) {
  if (verdict == "converged") return 2;
  if (verdict == "pre-asymptotic") return 1;
  return 0;
}

// The finest grid's RDE, +∞ without one (an unknown error ranks as large).
double finest_rde(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty() || !s.extrapolation->grids.front().rde)
    return std::numeric_limits<double>::infinity();
  return *s.extrapolation->grids.front().rde;
}

}  // namespace

Table verdict_count_table(const std::vector<SeriesSummary>& series) {
  const auto words = verdict_words(series);
  Table t;
  t.columns = {{"factor", {}, false, false, false}, {"level", {}, false, false, false},
               {"series", {}, false, true, false}};
  for (const auto& w : words) t.columns.push_back({w, {}, false, true, false});
  t.columns.push_back({"incomplete", {}, false, true, false});
  Tally all;
  for (const auto& s : series) all.add(s);
  t.rows.push_back(tally_row("all", "", all, words));
  if (series.empty()) return t;
  std::vector<std::vector<std::pair<std::string, std::string>>> factors;
  factors.reserve(series.size());
  for (const auto& s : series) factors.push_back(series_factors(s.series));
  for (std::size_t k = 0; k < factors.front().size(); ++k) {
    std::vector<std::string> levels;  // first-seen order
    std::map<std::string, Tally> tallies;
    for (std::size_t i = 0; i < series.size(); ++i) {
      const std::string& level = factors[i][k].second;
      if (!tallies.count(level)) levels.push_back(level);
      tallies[level].add(series[i]);
    }
    if (levels.size() < 2 || levels.size() > kShownRows) continue;
    for (const auto& level : levels) t.rows.push_back(tally_row(factors.front()[k].first, level, tallies[level], words));
  }
  return t;
}

std::vector<std::size_t> worst_series(const std::vector<SeriesSummary>& series, std::size_t max) {
  std::vector<std::size_t> order(series.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto key = [&series](std::size_t i) {
    return std::make_tuple(verdict_rank(series[i].verdict), -finest_rde(series[i]), i);
  };
  const std::size_t n = std::min(max, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                    [&key](std::size_t a, std::size_t b) { return key(a) < key(b); });
  order.resize(n);
  return order;
}

}  // namespace gridfree
