// Assembles the ReportContent from the study data (see report_content.h).
#include "report/report_content.h"

#include "report/cost_table.h"
#include "report/report_tables.h"

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

ReportContent build_report_content(const StudyReportData& data, const Extrapolator& extrapolate) {
  ReportContent c;
  c.data = data;
  c.series = summarize_series(data, extrapolate);
  c.differences = one_factor_differences(c.series);
  c.series_table = {"series.csv", "Series and extrapolation", series_table(c.series)};
  c.differences_table = {"differences.csv", "Relative differences between series (one factor changed)",
                         differences_table(c.series, c.differences)};
  c.cost_table = {"cost.csv", "What a target costs (speed vs accuracy)", cost_table(c.series)};
  c.gci_table = {"gci.csv", "Classic three-grid Richardson extrapolation / GCI", gci_table(c.series)};
  c.grids_table = {"grids.csv", "Every grid", grids_table(c.series)};
  c.failures_table = {"failures.csv", "Failures", failures_table(c.series)};
  c.coverage_table = {"coverage.csv", "Coverage self-check", coverage_table(c.series)};
  c.alignment = alignment_lines(data.alignment, c.series);
  c.alignment_table = {"alignment.csv", "Alignment check", alignment_table(c.alignment)};
  c.charts = report_charts(c.series, data.target_rde);
  c.ensembles = ensemble_section(c.series, data.ensembles);
  return c;
}

}  // namespace gridfree
