// SPDX-License-Identifier: GPL-3.0-or-later
// The report's first screen (docs/REPORTS.md "First screen"): the answer
// before anything else — the study's verdict counts and, for up to
// kAnswerRows series, f0 ± U₀ and the finest grid's f₁ ± U₁ with the verdict
// — then what needs attention: every series with a concern
// (series_concerns.h), ranked and linked, the first kShownWarnings listed and
// "… and N more" pointing at the series table's filter (`attention:yes`).
// Metadata, contents and file lists come after it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "report/report_content.h"

namespace gridfree {

inline constexpr std::size_t kAnswerRows = 12;  // series rows of the answer table

struct AnswerRow {
  std::size_t series = 0;
  std::string label, verdict;
  std::string f0;   // "1015.9 ± 1.5", or f0 to U₁'s digits "(no U₀)", or "—"
  std::string f1;   // "1017.0 ± 1.5 at Δ* 0.5", or "—"
};

struct AttentionLine {
  std::size_t series = 0;
  std::string label, text;   // text: the concerns joined by "; "
};

struct FirstScreen {
  std::string counts;                    // "2 series: 1 converged, 1 pre-asymptotic"
  std::vector<AnswerRow> rows;           // at most kAnswerRows, study order
  std::size_t more_series = 0;           // series not in rows
  std::vector<AttentionLine> attention;  // the first kShownWarnings, ranked (full layout: all)
  std::size_t attention_total = 0;       // series with a concern
  std::vector<std::string> study_notes;  // alignment warnings and pending grids
};

FirstScreen first_screen(const ReportContent& content);

// Its HTML (links to series pages or verdict blocks) and Markdown.
std::string first_screen_html(const ReportContent& content);
std::string first_screen_markdown(const ReportContent& content);

// The id of a series' verdict block on the full page ("v-<slug>").
std::string verdict_anchor(const std::string& label);

}  // namespace gridfree
