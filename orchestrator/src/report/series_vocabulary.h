// SPDX-License-Identifier: GPL-3.0-or-later
// The words of a series' case and of a whole study (study/case_vocabulary.h)
// as the report knows them: an external series carries its quantity and
// declared h (report/external_labels.h), a particle-bed series none.
#pragma once

#include <string>
#include <vector>

#include "report/report_data.h"
#include "report/series_summary.h"
#include "study/case_vocabulary.h"

namespace gridfree {

CaseVocabulary series_vocabulary(const SeriesData& s);

// The study's words: its first series' case kind (a study holds one kind of
// case); iterations counted when any grid of any series reports some.
CaseVocabulary study_vocabulary(const std::vector<SeriesData>& series);
CaseVocabulary study_vocabulary(const std::vector<SeriesSummary>& series);

// "Δ* 0.5" / "h 0.0125": a cell size in running text (format_cell_size's digits).
std::string cell_size_text(const CaseVocabulary& v, double h);

}  // namespace gridfree
