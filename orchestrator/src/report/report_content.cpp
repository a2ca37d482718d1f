// SPDX-License-Identifier: GPL-3.0-or-later
// Assembles the ReportContent from the study data (see report_content.h).
#include "report/report_content.h"

#include <algorithm>

#include "report/bed_about.h"
#include "report/cost_table.h"
#include "report/chart_common.h"
#include "report/report_tables.h"
#include "report/verdict_counts.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

int count_grids(const ReportContent& c, bool (*pred)(const GridPoint&)) {
  int n = 0;
  for (const auto& s : c.series) {
    for (const auto& g : s.series.grids) n += pred(g) ? 1 : 0;
  }
  return n;
}

bool any_grid(const GridPoint&) { return true; }

}  // namespace

int ReportContent::grids_total() const { return count_grids(*this, any_grid); }
int ReportContent::grids_converged() const { return count_grids(*this, is_converged); }
int ReportContent::grids_failed() const { return count_grids(*this, is_failed); }
int ReportContent::grids_pending() const { return count_grids(*this, is_pending); }

NamedTable head_of_series_tables(const std::vector<SeriesSummary>& series, std::string file, std::string title,
                                 const std::function<Table(const std::vector<SeriesSummary>&)>& of_series) {
  NamedTable out{std::move(file), std::move(title), of_series({}), 0};
  for (const auto& s : series) {
    Table one = of_series({s});
    out.total_rows += one.rows.size();
    for (auto& row : one.rows)
      if (out.table.rows.size() < kShownRows) out.table.rows.push_back(std::move(row));
  }
  return out;
}

std::string series_page_file(const ReportContent& content, std::size_t i) {
  return "series/" + series_slug(content.series[i], i) + ".html";
}

std::vector<AboutSection> study_about_sections(const ReportContent& content) {
  std::vector<AboutSection> out = about_sections(content.data.generator_kinds);
  std::vector<std::string> cases;
  for (const auto& s : content.series) cases.push_back(s.series.case_name);
  if (auto beds = bed_about_section(cases, content.data.beds, content.data.ensembles)) out.push_back(std::move(*beds));
  return out;
}

ReportContent build_report_content(const StudyReportData& data, const Extrapolator& extrapolate) {
  ReportContent c;
  // Everything but the series, which live on in c.series (one copy, not two).
  c.data.study_name = data.study_name;
  c.data.status = data.status;
  c.data.submitted_at = data.submitted_at;
  c.data.finished_at = data.finished_at;
  c.data.version = data.version;
  c.data.baseline_description = data.baseline_description;
  c.data.extrapolation_method = data.extrapolation_method;
  c.data.p_low = data.p_low;
  c.data.p_high = data.p_high;
  c.data.expected_order = data.expected_order;
  c.data.generator_kinds = data.generator_kinds;
  c.data.target_rde = data.target_rde;
  c.data.export_charts = data.export_charts;
  c.data.adaptive_decisions = data.adaptive_decisions;
  c.data.alignment = data.alignment;
  c.data.ensembles = data.ensembles;
  c.data.beds = data.beds;
  c.layout = layout_for(data.series.size());
  c.series = summarize_series(data, extrapolate);
  c.differences = one_factor_differences(c.series);
  c.series_table = {"series.csv", "Series and extrapolation", series_table(c.series, data.p_low, data.p_high)};
  // Summary layout: the largest differences first, the page shows the first rows.
  std::vector<SeriesDifference> shown = c.differences;
  if (c.layout == ReportLayout::summary)
    std::stable_sort(shown.begin(), shown.end(), [](const SeriesDifference& a, const SeriesDifference& b) {
      return a.relative.value_or(-1.0) > b.relative.value_or(-1.0);
    });
  c.differences_table = {"differences.csv", "Relative differences between series (one factor changed)",
                         differences_table(c.series, shown)};
  c.cost_table = {"cost.csv", "What a target costs (speed vs accuracy)", cost_table(c.series)};
  if (c.layout == ReportLayout::summary) {
    c.gci_table = head_of_series_tables(c.series, "gci.csv", "Classic three-grid Richardson extrapolation / GCI",
                                        [&](const std::vector<SeriesSummary>& one) {
                                          return gci_table(one, data.p_low, data.p_high);
                                        });
    c.grids_table = head_of_series_tables(c.series, "grids.csv", "Every grid", grids_table);
  } else {
    c.gci_table = {"gci.csv", "Classic three-grid Richardson extrapolation / GCI", gci_table(c.series, data.p_low, data.p_high)};
    c.grids_table = {"grids.csv", "Every grid", grids_table(c.series)};
  }
  c.failures_table = {"failures.csv", "Failures", failures_table(c.series)};
  c.coverage_table = {"coverage.csv", "Coverage self-check", coverage_table(c.series)};
  c.alignment = alignment_lines(data.alignment, c.series);
  c.alignment_table = {"alignment.csv", "Alignment check", alignment_table(c.alignment)};
  // Per factor level only when some factor has levels to count.
  Table counts = verdict_count_table(c.series);
  c.verdict_count_table = {"verdict_counts.csv", counts.rows.size() > 1 ? "Verdicts per factor level" : "Verdicts",
                           std::move(counts)};
  const CaseVocabulary words = study_vocabulary(c.series);
  for (NamedTable* t : {&c.series_table, &c.differences_table, &c.cost_table, &c.gci_table, &c.grids_table,
                        &c.failures_table, &c.coverage_table, &c.verdict_count_table})
    t->words = words;
  if (c.layout == ReportLayout::summary) {
    c.charts = study_charts(c.series, data.target_rde, c.layout, data.p_low, data.p_high);
    for (std::size_t i = 0; i < c.series.size(); ++i) c.series_table.table.rows[i][0].href = series_page_file(c, i);
  } else {
    c.charts = report_charts(c.series, data.target_rde);
  }
  c.ensembles = ensemble_section(c.series, data.ensembles);
  return c;
}

}  // namespace gridfree
