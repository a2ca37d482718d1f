// SPDX-License-Identifier: GPL-3.0-or-later
// Summary items and reading notes for the report documents.
#include "report/report_summary.h"

#include "extrap/verdict.h"
#include "report/extrapolator.h"
#include "report/series_coverage.h"
#include "extrap/value_format.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

std::vector<std::pair<std::string, std::string>> summary_items(const ReportContent& c) {
  const StudyReportData& d = c.data;
  std::vector<std::pair<std::string, std::string>> items = {
      {"Study", d.study_name},
      {"Status", d.status},
      {"Submitted", d.submitted_at},
      {"Finished", d.finished_at},
      // A design is worth naming only when the series vary some factor (an
      // external study without factors is not "factorial").
      {"Design", c.verdict_count_table.table.rows.size() > 1 ? d.baseline_description : std::string()},
      {"Extrapolation", d.extrapolation_method + " (power law accepted for " + format_g(d.p_low, 4) +
                            " ≤ p ≤ " + format_g(d.p_high, 4) + ")"},
      {"Measured coverage", measured_coverage_line(d.extrapolation_method, d.expected_order.has_value())},
      {"Series", std::to_string(c.series.size())},
      {"Coverage self-check", coverage_summary(c.series)},
      // Grids are "solved" (their solver converged); "converged" is a series' verdict.
      {"Grids", std::to_string(c.grids_total()) + " (" + std::to_string(c.grids_converged()) + " solved, " +
                    std::to_string(c.grids_failed()) + " failed (no value), " +
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
  for (auto& w : alignment_warnings(c.alignment)) out.push_back(std::move(w));
  for (auto& w : coverage_warnings(c.series)) out.push_back(std::move(w));
  return out;
}

VerdictItem verdict_item(const SeriesSummary& s) {
  VerdictItem item{s.label, s.verdict, {}, s.verdict_reasons, {}};
  if (const auto f0 = s.f0()) {
    const auto& grids = s.extrapolation->grids;
    const std::optional<double> u = grids.empty() ? std::nullopt : grids.front().u;
    // Each value with its own interval: f0 ± U₀, f₁ ± U₁ (U₁ is about
    // f₁, never printed with f0; docs/EXTRAPOLATION.md "U₀").
    const std::optional<double> u0 = s.extrapolation->u0;
    item.headline = "f0 = " + (u0 ? format_with_uncertainty(*f0, u0) + " (U₀)" : format_to_uncertainty_digits(*f0, u));
    if (!grids.empty())
      item.headline += "; finest grid " + series_vocabulary(s.series).h_symbol + " = " +
                       format_cell_size(grids.front().h) + ": f₁ = " +
                       format_with_uncertainty(grids.front().f, u) +
                       (u ? " (U₁, RDE " + format_percent(grids.front().rde) + ")" : "");
  } else {
    item.headline = "no extrapolated value";
  }
  const std::string note = s.note();
  if (!note.empty()) item.notes.push_back(note);
  if (s.extrapolation)
    for (const auto& n : s.extrapolation->notes) item.notes.push_back(n);
  return item;
}

std::vector<VerdictItem> verdict_items(const ReportContent& c) {
  std::vector<VerdictItem> out;
  out.reserve(c.series.size());
  for (const auto& s : c.series) out.push_back(verdict_item(s));
  return out;
}

std::string reading_note(const std::string& section, const CaseVocabulary& words) {
  if (section == "alignment.csv") return alignment_reading_note();
  if (section == "series.csv") {
    return std::string("f0 is the extrapolated (grid-free) ") + words.value_noun +
           ". The power law f0 + c·h^p is used when its exponent is "
           "found inside the accepted range; with the methods averaged (the default) and capped an exponent above "
           "the range is capped at its upper end (f0 + c·h^p_high), otherwise the mixed-order fit f0 + c1·h + c2·h² "
           "is used. U₀ = 1.25|f0 − f₁| + σ_RE is f0's own uncertainty (f₁ the finest grid's value); averaged "
           "widens U and U₀ to hold f0 of every error expansion that describes the data, and every method to "
           "hold the fits without the coarsest and without the finest grid (docs/EXTRAPOLATION.md). σ_RE is the "
           "standard deviation of the weighted fit, R_f = (max f − min f)/(ng − 1) the data range; "
           "σ_RE/R_f < 1 is a good fit when at least 2 degrees of freedom (ng ≥ 5) are left; with fewer the fit "
           "cannot be judged. Fs = max(1.25, 3σ_RE/R_f) is the safety factor of U. "
           "Series with fewer than 4 converged grids get no uncertainty. The verdict follows from these "
           "numbers by the rules of docs/EXTRAPOLATION.md (the verdict section above gives the reasons).";
  }
  if (section == "verdicts") {
    const VerdictRules r;
    const std::string k = format_g(r.envelope_k, 3);
    return "Each series' verdict follows from its extrapolation by the rules of docs/EXTRAPOLATION.md: "
           "converged (observed order in the accepted range, σ_RE/R_f < 1, f0 within " + k +
           " R_f of the data, at least " + std::to_string(r.min_dof) + " degrees of freedom, finest-grid RDE ≤ " +
           format_percent(r.rde_converged) + "), pre-asymptotic (the data do not yet show the asymptotic "
           "range: add the finer grid named), unreliable (f0 more than " + k + " R_f beyond the data, fewer than " +
           std::to_string(3 + r.min_dof) + " grids, or finest-grid RDE above " + format_percent(r.rde_unreliable) +
           "), insufficient_grids (fewer than 4 converged grids).";
  }
  if (section == "differences.csv") {
    return "Pairs of series that differ in exactly one factor, and 2|f0a − f0b|/(f0a + f0b): the effect of "
           "that factor" + (words.model_form.empty() ? std::string() : " (model form: " + words.model_form + ")") +
           " on the grid-free answer. It is beyond the uncertainty when |f0a − f0b| > √(U_a² + U_b²), U of each series' finest "
           "grid (shown relative to the mean f0). Differences between series that are not both converged "
           "are marked ⚠: their f0 may move when grids are added. A factor of more than 12 levels (the "
           "instances of a large ensemble) pairs no series: the ensemble section gives their spread.";
  }
  if (section == "coverage.csv") {
    return "Does the uncertainty cover the answer? For every series with all its grids and at least 6 converged, "
           "each window of 4 to 8 consecutive grids without the finest one is extrapolated again by the same "
           "method, and its finest grid's interval f₁ ± U₁ (and f0 ± U₀) is compared with f0 of the whole "
           "series. The default method was measured to cover the answer in at least 95 % of such windows in "
           "every verdict class (docs/EXTRAPOLATION.md \"Coverage\"); a series below that is listed under "
           "Attention. The windows share grids, so the misses are not independent: one pre-asymptotic stretch "
           "of coarse grids can miss in several windows.";
  }
  if (section == "cost.csv") {
    return "For each target RDE, the cheapest converged grid (least CPU time) whose RDE meets it and "
           "stays within it on every finer grid, with its cost in CPU seconds (this machine), " +
           (words.iterations_counted ? "in cells × " + words.iteration + "s (any machine) "
                                     : std::string("its cells (the code reports no iterations) ")) +
           "and its peak memory. RDE is the a-priori error estimate U/|f0| of "
           "that grid from the series' extrapolation; \"none of the run grids\" means a finer grid is "
           "needed. On oscillatory convergence a coarse grid can land near f0 by chance: its small RDE "
           "does not count while a finer grid misses the target. A series that is not `converged` "
           "names no grid (\"— (series pre-asymptotic)\"): its extrapolation may still move.";
  }
  if (section == "gci.csv") {
    return "The classic three-grid procedure (apparent order by fixed-point iteration, φ_ext and "
           "GCI_fine = 1.25|f1 − f2|/(r^p − 1)) for every consecutive triplet. On oscillatory data its "
           "answers scatter; compare φ_ext with the regression's f0 in the last column.";
  }
  if (section == "grids.csv") {
    return std::string("Every job: U = Fs|f0 − f_i| + σ_RE is the uncertainty of its ") +
           words.grid_value_noun + ", RDE = U/|f0|.";
  }
  if (section == "failures.csv") {
    return "Grids that finished without a usable value. They are left out of the fits and shown with "
           "× markers in the charts (on the axis when they have no value).";
  }
  return {};
}

}  // namespace gridfree
