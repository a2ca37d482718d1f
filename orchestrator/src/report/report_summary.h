// SPDX-License-Identifier: GPL-3.0-or-later
// The study summary and the reading notes shared by report.md and
// report.html, as plain text (each renderer escapes it for its format).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "report/report_content.h"
#include "study/case_vocabulary.h"

namespace gridfree {

// ("Study", "bursting-bubble"), ("Status", "done"), ... in display order;
// empty values are left out.
std::vector<std::pair<std::string, std::string>> summary_items(const ReportContent& content);

// Series that are incomplete or have insufficient grids, one line each.
std::vector<std::string> series_warnings(const ReportContent& content);

// What the verdict section shows for one series (docs/EXTRAPOLATION.md
// "Verdicts"): the verdict word, a headline with f0 ± U rounded to the
// digits U supports, the reasons and any notes in words.
struct VerdictItem {
  std::string label, verdict, headline;
  std::vector<std::string> reasons, notes;
};
VerdictItem verdict_item(const SeriesSummary& series);
std::vector<VerdictItem> verdict_items(const ReportContent& content);  // every series, in order

// One short paragraph per section on how to read it (keyed by CSV/section name).
// `words`: the study's case words (an external study's declared quantity
// and h, not DP* and Δ*; no particle-bed model form; iterations if counted).
std::string reading_note(const std::string& section,
                         const CaseVocabulary& words = case_vocabulary(CaseKindId::particle_bed));

}  // namespace gridfree
