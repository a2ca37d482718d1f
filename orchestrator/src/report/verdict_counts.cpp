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

}  // namespace gridfree
