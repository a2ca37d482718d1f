// SPDX-License-Identifier: GPL-3.0-or-later
// A series' and a study's case words (see series_vocabulary.h).
#include "report/series_vocabulary.h"

#include "extrap/value_format.h"

namespace gridfree {
namespace {

bool any_iterations(const SeriesData& s) {
  for (const auto& g : s.grids)
    if (g.iterations > 0) return true;
  return false;
}

}  // namespace

CaseVocabulary series_vocabulary(const SeriesData& s) {
  if (s.quantity.empty()) return case_vocabulary(CaseKindId::particle_bed);
  CaseVocabulary v = case_vocabulary(CaseKindId::external, s.h_label, s.quantity, s.quantity_label);
  v.iterations_counted = any_iterations(s);
  return v;
}

CaseVocabulary study_vocabulary(const std::vector<SeriesData>& series) {
  if (series.empty()) return case_vocabulary(CaseKindId::particle_bed);
  CaseVocabulary v = series_vocabulary(series.front());
  if (v.kind == CaseKindId::particle_bed) return v;
  for (const auto& s : series) v.iterations_counted = v.iterations_counted || any_iterations(s);
  return v;
}

CaseVocabulary study_vocabulary(const std::vector<SeriesSummary>& series) {
  if (series.empty()) return case_vocabulary(CaseKindId::particle_bed);
  CaseVocabulary v = series_vocabulary(series.front().series);
  if (v.kind == CaseKindId::particle_bed) return v;
  for (const auto& s : series) v.iterations_counted = v.iterations_counted || any_iterations(s.series);
  return v;
}

std::string cell_size_text(const CaseVocabulary& v, double h) { return v.h_symbol + " " + format_cell_size(h); }

}  // namespace gridfree
