// SPDX-License-Identifier: GPL-3.0-or-later
// How a report is laid out for the number of series it shows
// (docs/REPORTS.md "Large studies").
//
// Up to kFullPageSeries series the study page holds everything: every
// series' verdict, charts and table rows. Beyond that a page with every
// series' charts inline grows by about 50 KB a series (27 MB at 540 series)
// and no reader scrolls it; the study page then summarises (verdict counts
// per factor level, the worst series, aggregated and sampled charts, long
// tables cut to their first rows with the whole table in its CSV) and every
// series gets a page of its own under series/, written only when it changed.
#pragma once

#include <cstddef>

namespace gridfree {

inline constexpr std::size_t kFullPageSeries = 24;   // the largest study shown whole on one page
inline constexpr std::size_t kShownRows = 50;        // rows of a long table on the summary page
inline constexpr std::size_t kWorstSeries = 20;      // Markdown: series listed under "Series that need a look"
inline constexpr std::size_t kShownWarnings = 20;    // attention lines before "… and N more"
inline constexpr std::size_t kSpeedAccuracyWorst = 4;    // speed-accuracy: series that most need a look
inline constexpr std::size_t kSpeedAccuracyCheapest = 3; // … and the cheapest converged ones

enum class ReportLayout { full_page, summary };

constexpr ReportLayout layout_for(std::size_t series) {
  return series > kFullPageSeries ? ReportLayout::summary : ReportLayout::full_page;
}

}  // namespace gridfree
