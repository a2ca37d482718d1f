// SPDX-License-Identifier: GPL-3.0-or-later
// Builders of the report tables (see report_tables.h).
#include "report/report_tables.h"

#include <algorithm>
#include <optional>
#include <set>

#include "extrap/verdict.h"
#include "extrap/value_format.h"
#include "report/series_concerns.h"
#include "report/series_coverage.h"
#include "report/series_vocabulary.h"
#include "report/stability_map.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

Column text_col(std::string name, std::string title = {}, bool csv_only = false) {
  return {std::move(name), std::move(title), csv_only, false};
}
Column prose_col(std::string name, std::string title = {}) {
  return {std::move(name), std::move(title), false, false, true};
}
Column num_col(std::string name, std::string title = {}, bool csv_only = false) {
  return {std::move(name), std::move(title), csv_only, true};
}
// Shown on screen, not printed: fit details series.csv keeps, so the printed
// series table fits a portrait page.
Column screen_only(Column c) {
  c.screen_only = true;
  return c;
}

bool all_external(const std::vector<SeriesSummary>& series);

// The study's own factor names of external series (docs/EXTERNAL.md
// "Factors, designs and ensembles"), in name order.
// A factor named like a column of the grids or series table has no column
// of its own (its level is in `levels`).
std::vector<std::string> external_factor_names(const std::vector<SeriesSummary>& series) {
  static const std::set<std::string> kTaken = {
      "series", "f0", "verdict", "attention", "concerns", "case", "quantity", "levels", "status", "grids", "ng",
      "failed", "pending", "method", "u0", "p", "c", "c1", "c2", "f0_power", "p_power", "p_found", "f0_mixed",
      "sigma_re", "data_range", "sigma_re_over_rf", "good_fit", "fs", "verdict_reasons", "note",
      "extrapolation_notes", "job_hash", "h", "delta_star", "nx", "ny", "nz", "cells", "value", "dp_star", "fhat",
      "u", "rde", "error_vs_f0", "iterations", "wall_s", "cpu_s", "peak_rss_mb", "reason"};
  std::set<std::string> names;
  for (const auto& s : series)
    for (const auto& [name, level] : s.series.levels)
      if (kTaken.count(name) == 0) names.insert(name);
  return {names.begin(), names.end()};
}

// Factor columns present in the CSV of the grids and series tables: the
// particle bed's, or an external study's case, quantity, one column per
// factor and the levels as JSON (the database's `levels`).
void add_factor_columns(std::vector<Column>& columns, const std::vector<std::string>& factor_names, bool external) {
  if (external) {
    columns.push_back(text_col("case", {}, true));
    columns.push_back(text_col("quantity", {}, true));
    for (const auto& name : factor_names) columns.push_back(text_col(name, {}, true));
    columns.push_back(text_col("levels", {}, true));
    return;
  }
  for (const char* f : {"case", "convection", "fwhm_dp", "drag", "deposition"}) {
    columns.push_back(text_col(f, {}, true));
  }
}

void add_factor_cells(std::vector<Cell>& row, const SeriesData& s, const std::vector<std::string>& factor_names,
                      bool external) {
  row.push_back(text_cell(s.case_name));
  if (external) {
    row.push_back(text_cell(s.quantity));
    for (const auto& name : factor_names) {
      const auto level = s.levels.find(name);
      row.push_back(text_cell(level == s.levels.end() ? std::string() : level->second));
    }
    nlohmann::json levels = nlohmann::json::object();
    for (const auto& [name, level] : s.levels) levels[name] = level;
    row.push_back(text_cell(levels.dump()));
    return;
  }
  row.push_back(text_cell(s.convection));
  row.push_back(number_cell(s.fwhm_dp));
  row.push_back(text_cell(s.drag));
  row.push_back(text_cell(s.deposition.empty() ? "diffusion" : s.deposition));
}

std::string series_status(const SeriesSummary& s) {
  std::string status = s.series.status.empty() ? "unknown" : s.series.status;
  if (s.incomplete && status != "running" && status != "queued") status += " (incomplete)";
  return status;
}

// An external study's series (docs/EXTERNAL.md): its own factor columns.
bool all_external(const std::vector<SeriesSummary>& series) {
  return !series.empty() && !study_vocabulary(series).particle_factors;
}

// The case's h and value columns: "delta_star" shown "Δ*", or "h".
Column h_col(const CaseVocabulary& v, const std::string& suffix = {}) {
  return num_col(v.h_column + suffix, v.h_symbol + suffix);
}
Column value_col(const CaseVocabulary& v) {
  return num_col(v.value_column, v.value_column == "value" ? std::string() : v.quantity_symbol);
}

}  // namespace

Table grids_table(const std::vector<SeriesSummary>& series) {
  Table t;
  // The case's words: an external study's CSV names h and the value (its
  // quantity is in the series column), a count of cells, no nx × ny × nz.
  const CaseVocabulary v = study_vocabulary(series);
  const bool external = all_external(series);
  t.columns.push_back(text_col("series"));
  const std::vector<std::string> factor_names = external_factor_names(series);
  add_factor_columns(t.columns, factor_names, external);
  t.columns.push_back(text_col("job_hash", {}, true));
  t.columns.push_back(h_col(v));
  for (const char* n : {"nx", "ny", "nz"}) t.columns.push_back(num_col(n, {}, true));
  t.columns.push_back(num_col("cells"));
  t.columns.push_back(text_col("status"));
  t.columns.push_back(value_col(v));
  t.columns.push_back(num_col("fhat", "fit", true));
  t.columns.push_back(num_col("u", "U"));
  t.columns.push_back(num_col("rde", "RDE"));
  t.columns.push_back(num_col("error_vs_f0", "|f−f0|/f0", true));
  t.columns.push_back(num_col("iterations"));
  t.columns.push_back(num_col("wall_s", "wall s"));
  t.columns.push_back(num_col("cpu_s", "CPU s"));
  t.columns.push_back(num_col("peak_rss_mb", "RSS MB"));
  t.columns.push_back(prose_col("reason"));
  for (const auto& s : series) {
    for (const GridPoint& g : s.series.grids) {
      const ExtrapolatedGrid* e = s.extrapolated(g);
      std::vector<Cell> row;
      row.push_back(text_cell(s.label));
      add_factor_cells(row, s.series, factor_names, external);
      row.push_back(text_cell(g.job_hash));
      row.push_back(number_cell(g.delta_star, 4));
      const long long cells = static_cast<long long>(g.nx) * g.ny * g.nz;
      for (int n : {g.nx, g.ny, g.nz}) row.push_back(v.cells_per_direction ? integer_cell(n) : text_cell(""));
      if (!v.cells_per_direction)  // the declared cell count, not a "400×1×1" box
        row.push_back(integer_cell(cells));
      else
        row.push_back({std::to_string(cells), std::to_string(g.nx) + "×" + std::to_string(g.ny) + "×" +
                                                  std::to_string(g.nz) + " (" + std::to_string(cells) + ")"});
      row.push_back(text_cell(g.status));
      row.push_back(number_cell(g.dp_star, 7));
      row.push_back(number_cell(e ? e->fhat : std::nullopt, 7));
      row.push_back(number_cell(e ? e->u : std::nullopt, 3));
      row.push_back(percent_cell(e ? e->rde : std::nullopt));
      row.push_back(percent_cell(is_converged(g) ? s.relative_error(*g.dp_star) : std::nullopt));
      // A code that reports no iterations leaves the cell empty, not 0.
      row.push_back(v.iterations_counted ? integer_cell(g.iterations) : text_cell(""));
      row.push_back(number_cell(g.wall_s, 3));
      row.push_back(number_cell(g.cpu_s, 3));
      row.push_back(number_cell(g.peak_rss_mb, 4));
      row.push_back(text_cell(g.reason));
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

Table series_table(const std::vector<SeriesSummary>& series, double p_low, double p_high) {
  Table t;
  // The series' name and f0 ± U₀ first: a narrow screen shows them without
  // scrolling sideways (the f0 cell prints U₀ with it; U0 stays in the CSV).
  t.columns.push_back(text_col("series"));
  t.columns.push_back(num_col("f0", "f0 ± U₀"));
  t.columns.push_back(text_col("verdict"));
  t.columns.push_back(text_col("attention", {}, true));
  t.columns.push_back(text_col("concerns", {}, true));
  const bool external = all_external(series);
  const std::vector<std::string> factor_names = external_factor_names(series);
  add_factor_columns(t.columns, factor_names, external);
  t.columns.push_back(text_col("status"));
  t.columns.push_back(num_col("grids"));
  t.columns.push_back(num_col("ng", "ng (converged)"));
  t.columns.push_back(num_col("failed"));
  t.columns.push_back(num_col("pending", {}, true));
  t.columns.push_back(text_col("method"));
  t.columns.push_back(num_col("u0", "U0", true));
  t.columns.push_back(num_col("p"));
  t.columns.push_back(screen_only(num_col("c")));
  t.columns.push_back(screen_only(num_col("c1")));
  t.columns.push_back(screen_only(num_col("c2")));
  t.columns.push_back(num_col("f0_power", {}, true));
  t.columns.push_back(num_col("p_power", {}, true));
  t.columns.push_back(text_col("p_found", {}, true));
  t.columns.push_back(num_col("f0_mixed", {}, true));
  t.columns.push_back(screen_only(num_col("sigma_re", "σ_RE")));
  t.columns.push_back(screen_only(num_col("data_range", "R_f")));
  t.columns.push_back(num_col("sigma_re_over_rf", "σ_RE/R_f"));
  t.columns.push_back(text_col("good_fit", "good fit"));
  t.columns.push_back(screen_only(num_col("fs", "Fs")));
  // Long texts are CSV-only here; the report prints them per series in its
  // verdict section, so the table keeps to the page width.
  t.columns.push_back(text_col("verdict_reasons", {}, true));
  t.columns.push_back(text_col("note", {}, true));
  t.columns.push_back(text_col("extrapolation_notes", {}, true));
  const auto concerns = series_concerns(series, p_low, p_high);
  std::vector<const SeriesConcerns*> concern_of(series.size(), nullptr);
  for (const auto& c : concerns) concern_of[c.series] = &c;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const SeriesSummary& s = series[i];
    const ExtrapolationView empty;
    const ExtrapolationView& e = s.extrapolation ? *s.extrapolation : empty;
    std::vector<Cell> row;
    row.push_back(text_cell(s.label));
    Cell f0 = number_cell(s.f0(), 8);
    if (const auto v = s.f0()) {
      const std::optional<double> u1 = e.grids.empty() ? std::nullopt : e.grids.front().u;
      f0.shown = e.u0 ? format_value_u(*v, e.u0) : format_value_for_u(*v, u1);
    }
    row.push_back(f0);
    row.push_back(text_cell(s.verdict));
    std::string concern_text;
    if (concern_of[i])
      for (const auto& c : concern_of[i]->concerns) concern_text += (concern_text.empty() ? "" : "; ") + c;
    row.push_back(text_cell(concern_of[i] ? "yes" : "no"));
    row.push_back(text_cell(concern_text));
    add_factor_cells(row, s.series, factor_names, external);
    row.push_back(text_cell(series_status(s)));
    row.push_back(integer_cell(static_cast<long long>(s.series.grids.size())));
    row.push_back(integer_cell(s.converged()));
    row.push_back(integer_cell(s.failed));
    row.push_back(integer_cell(s.pending));
    row.push_back(text_cell(e.method));
    row.push_back(number_cell(e.u0, 3));
    // p and c belong to the power law: shown only when it is the chosen fit
    // (the store keeps them NULL for a mixed fit; the rejected fit's values
    // stay in the CSV-only p_power and f0_power columns).
    const bool power_chosen = e.method == "power";
    row.push_back(number_cell(power_chosen ? e.p : std::nullopt, 3));
    row.push_back(number_cell(power_chosen ? e.power.c : std::nullopt, 4));
    row.push_back(number_cell(e.mixed.c1, 4));
    row.push_back(number_cell(e.mixed.c2, 4));
    row.push_back(number_cell(e.power.f0, 8));
    row.push_back(number_cell(e.power.p, 4));
    row.push_back(text_cell(s.extrapolation ? (e.power.p_found ? "yes" : "no") : ""));
    row.push_back(number_cell(e.mixed.f0, 8));
    row.push_back(number_cell(e.sigma_re, 3));
    row.push_back(number_cell(e.data_range, 3));
    const auto quality = e.fit_quality();
    row.push_back(number_cell(quality, 3));
    const bool judgeable = static_cast<int>(e.grids.size()) - 3 >= VerdictRules{}.min_dof;
    row.push_back(text_cell(quality ? (!judgeable ? "cannot be judged" : (*quality < 1 ? "yes" : "no")) : ""));
    row.push_back(number_cell(e.fs, 3));
    std::string reasons;
    for (const auto& r : s.verdict_reasons) reasons += (reasons.empty() ? "" : "; ") + r;
    row.push_back(text_cell(reasons));
    row.push_back(text_cell(s.note()));
    std::string notes;
    for (const auto& n : e.notes) notes += (notes.empty() ? "" : "; ") + n;
    row.push_back(text_cell(notes));
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table differences_table(const std::vector<SeriesSummary>& series,
                        const std::vector<SeriesDifference>& differences) {
  Table t;
  t.columns = {text_col("factor"),          text_col("value_a", "a"),   text_col("value_b", "b"),
               text_col("series_a", {}, true), text_col("series_b", {}, true), num_col("f0_a"),
               num_col("f0_b"),             num_col("relative_difference", "2|f0a−f0b|/(f0a+f0b)"),
               num_col("u_a", "U_a", true), num_col("u_b", "U_b", true),
               num_col("u_combined_relative", "2·√(U_a²+U_b²)/(f0a+f0b)"),
               text_col("exceeds_u", "beyond U?"), text_col("verdicts")};
  for (const auto& d : differences) {
    std::string verdicts = d.verdict_a + " / " + d.verdict_b;
    if (!d.both_converged()) verdicts = "⚠ " + verdicts;
    std::string exceeds = d.exceeds_u ? (*d.exceeds_u ? "yes" : "no") : "";
    t.rows.push_back({text_cell(d.factor), text_cell(d.value_a), text_cell(d.value_b),
                      text_cell(series[d.a].label), text_cell(series[d.b].label),
                      value_cell(d.f0_a, d.u_a), value_cell(d.f0_b, d.u_b), percent_cell(d.relative),
                      value_cell(d.u_a, d.u_a), value_cell(d.u_b, d.u_b), percent_cell(d.u_relative),
                      text_cell(exceeds), text_cell(verdicts)});
  }
  return t;
}

Table gci_table(const std::vector<SeriesSummary>& series, double p_low, double p_high) {
  Table t;
  const std::string h = study_vocabulary(series).h_symbol;  // h as declared, or Δ*
  t.columns = {text_col("series"),        num_col("h1", h + "1"), num_col("h2", h + "2"),
               num_col("h3", h + "3"),    num_col("p"),           num_col("f_ext", "φ_ext"),
               num_col("gci_fine", "GCI_fine"), text_col("convergence"), text_col("status"), text_col("usable"),
               num_col("f0", "f0 (regression)"), num_col("f_ext_vs_f0", "(φ_ext−f0)/f0")};
  for (const auto& s : series) {
    if (!s.extrapolation) continue;
    const auto f0 = s.f0();
    // φ_ext and f0 to the decimal U₀ supports, so the two compare digit by digit.
    const auto u0 = s.extrapolation->u0;
    for (const GciView& g : s.extrapolation->gci) {
      std::optional<double> deviation;
      if (g.f_ext && f0 && *f0 != 0) deviation = (*g.f_ext - *f0) / *f0;
      t.rows.push_back({text_cell(s.label), number_cell(g.h[0], 4), number_cell(g.h[1], 4),
                        number_cell(g.h[2], 4), number_cell(g.p, 3), value_cell(g.f_ext, u0),
                        percent_cell(g.gci_fine), text_cell(g.convergence), text_cell(g.status),
                        text_cell(gci_usability(g, p_low, p_high)), value_cell(f0, u0), percent_cell(deviation)});
    }
  }
  return t;
}

Table failures_table(const std::vector<SeriesSummary>& series) {
  Table t;
  const CaseVocabulary v = study_vocabulary(series);
  t.columns = {text_col("series"), h_col(v), num_col("cells"), text_col("status"), value_col(v), prose_col("reason"),
               text_col("job_hash", {}, true)};
  for (const auto& s : series) {
    for (const GridPoint& g : s.series.grids) {
      if (!is_failed(g)) continue;
      t.rows.push_back({text_cell(s.label), number_cell(g.delta_star, 4),
                        integer_cell(static_cast<long long>(g.nx) * g.ny * g.nz), text_cell(g.status),
                        number_cell(g.dp_star, 7), text_cell(g.reason.empty() ? "(no reason recorded)" : g.reason),
                        text_cell(g.job_hash)});
    }
  }
  return t;
}

Table coverage_table(const std::vector<SeriesSummary>& series) {
  Table t;
  t.columns = {text_col("series"),
               text_col("verdict"),
               num_col("grids", "ng"),
               num_col("reference", "f0 (all grids)", true),
               num_col("windows"),
               num_col("covered_u1", "U1 covers"),
               num_col("covered_u0", "U0 covers"),
               num_col("coverage"),
               num_col("worst", "max miss/U1"),
               text_col("status", {}, true),
               prose_col("missed", "windows that missed (" + study_vocabulary(series).h_symbol + " coarse–fine)")};
  for (const auto& s : series) {
    if (!s.coverage) continue;
    const CoverageCheck& c = *s.coverage;
    const std::string status = c.status != "checked" ? c.status : (c.below_promise() ? "below promise" : "ok");
    t.rows.push_back({text_cell(s.label), text_cell(s.verdict), integer_cell(static_cast<long long>(s.h.size())),
                      number_cell(c.reference, 8), integer_cell(c.judged), integer_cell(c.covered),
                      integer_cell(c.f0_covered), percent_cell(coverage_rate(c), 3),
                      number_cell(worst_distance(c), 3), text_cell(status), text_cell(missed_windows(c, series_vocabulary(s.series).h_symbol))});
  }
  return t;
}

std::string csv_by_series(const std::vector<SeriesSummary>& series,
                          const std::function<Table(const std::vector<SeriesSummary>&)>& of_series) {
  // The header from the first series' table: an external study's names h and value.
  Table head = of_series(series.empty() ? std::vector<SeriesSummary>{} : std::vector<SeriesSummary>{series.front()});
  head.rows.clear();
  std::string out = to_csv(head);
  for (const auto& s : series) out += to_csv(of_series({s}), false);
  return out;
}

}  // namespace gridfree
