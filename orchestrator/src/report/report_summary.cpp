// Summary items and reading notes for the report documents.
#include "report/report_summary.h"

#include "report/text_format.h"

namespace gridfree {

std::vector<std::pair<std::string, std::string>> summary_items(const ReportContent& c) {
  const StudyReportData& d = c.data;
  std::vector<std::pair<std::string, std::string>> items = {
      {"Study", d.study_name},
      {"Status", d.status},
      {"Submitted", d.submitted_at},
      {"Finished", d.finished_at},
      {"Design", d.baseline_description},
      {"Extrapolation", d.extrapolation_method + " (power law accepted for " + format_g(d.p_low, 4) +
                            " ≤ p ≤ " + format_g(d.p_high, 4) + ")"},
      {"Series", std::to_string(c.series.size())},
      {"Grids", std::to_string(c.grids_total()) + " (" + std::to_string(c.grids_converged()) + " converged, " +
                    std::to_string(c.grids_failed()) + " failed or not converged, " +
                    std::to_string(c.grids_pending()) + " pending)"},
      {"Written by", d.version},
  };
  std::erase_if(items, [](const auto& kv) { return kv.second.empty(); });
  return items;
}

std::vector<std::string> series_warnings(const ReportContent& c) {
  std::vector<std::string> out;
  for (const auto& s : c.series) {
    const std::string note = s.note();
    if (!note.empty()) out.push_back(s.label + ": " + note);
  }
  return out;
}

std::string reading_note(const std::string& section) {
  if (section == "series.csv") {
    return "f0 is the extrapolated (grid-free) DP*. The power law f0 + c·h^p is used when its exponent is "
           "found inside the accepted range, otherwise the mixed-order fit f0 + c1·h + c2·h². σ_RE is the "
           "standard deviation of the weighted fit, R_f = (max f − min f)/(ng − 1) the data range; "
           "σ_RE/R_f < 1 is a good fit. Fs = max(1.25, 3σ_RE/R_f) is the safety factor of U. "
           "Series with fewer than 4 converged grids get no uncertainty.";
  }
  if (section == "differences.csv") {
    return "Pairs of series that differ in exactly one factor, and 2|f0a − f0b|/(f0a + f0b): the effect of "
           "that factor (model form: drag law, filter width, particle configuration) on the grid-free "
           "answer. Compare it with the RDE of the two series: a difference well above both RDEs is real.";
  }
  if (section == "gci.csv") {
    return "The classic three-grid procedure (apparent order by fixed-point iteration, φ_ext and "
           "GCI_fine = 1.25|f1 − f2|/(r^p − 1)) for every consecutive triplet. On oscillatory data its "
           "answers scatter; compare φ_ext with the regression's f0 in the last column.";
  }
  if (section == "grids.csv") {
    return "Every job: U = Fs|f0 − f_i| + σ_RE is the uncertainty of its DP*, RDE = U/|f0|.";
  }
  if (section == "failures.csv") {
    return "Grids that finished without a usable value. They are left out of the fits and shown with "
           "× markers in the charts (on the axis when they have no value).";
  }
  return {};
}

}  // namespace gridfree
