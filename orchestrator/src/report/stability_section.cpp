// SPDX-License-Identifier: GPL-3.0-or-later
// The "Where methods fail" section (stability_section.h).
#include "report/stability_section.h"

#include "report/report_tables.h"

#include <algorithm>

#include "report/atomic_file.h"
#include "extrap/value_format.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

Column stab_text(std::string name, std::string title = {}, bool prose = false) {
  Column c;
  c.title = title.empty() ? name : title;
  c.name = std::move(name);
  c.prose = prose;
  return c;
}

Column stab_num(std::string name, std::string title = {}) {
  Column c = stab_text(std::move(name), std::move(title));
  c.numeric = true;
  return c;
}

// A cell's short text in the map: the outer iterations of a solved grid
// ("✓" alone when the code reports none), else a short word.
std::string stability_cell_text(const StabilityCell& c, bool iterations_counted) {
  if (!c.present) return "";
  const std::string solved = iterations_counted ? "✓ " + std::to_string(c.iterations) : "✓";
  if (c.remedy_from > 0) return (c.outcome == "converged" ? solved : c.outcome) + " R";
  if (c.outcome == "converged") return solved;
  if (c.outcome == "iteration_cap") return "cap";
  if (c.outcome == "timed_out") return "timeout";
  if (c.outcome == "pending") return "…";
  return c.outcome;
}

struct OutcomeStyle {
  const char* outcome;
  const char* fill;
  const char* meaning;
  const char* any_code = nullptr;  // the meaning for a case that is not the worker's (no numerics.*, no ε_s)
};

// Colour-blind-safe fills (Okabe–Ito, lightened for the converged cells).
constexpr OutcomeStyle kOutcomeStyles[] = {
    {"converged", "#c7eadb", "solved"},  // the legend adds "(✓ <iterations>)" when they are counted
    {"stalled", "#f0e442", "stalled (a limit cycle: numerics.stall_window)", "stalled"},
    {"iteration_cap", "#e69f00", "cap: not converged at numerics.max_iterations", "cap: not converged"},
    {"diverged", "#d55e00", "diverged"},
    {"invalid", "#cc79a7", "invalid (no solution, e.g. ε_s ≥ 1 in a cell)", "invalid (no solution)"},
    {"timed_out", "#56b4e9", "timed out"},
    {"failed", "#999999", "failed"},
    {"pending", "#ffffff", "not finished"},
    {"cancelled", "#eeeeee", "cancelled"},
};

const OutcomeStyle& outcome_style_of(const std::string& outcome) {
  for (const auto& s : kOutcomeStyles)
    if (outcome == s.outcome) return s;
  return kOutcomeStyles[6];
}

std::string stability_methods_text(const MethodTally& t) {
  std::string out = "GCI usable in " + std::to_string(t.gci_usable) + " of " + std::to_string(t.triplets) +
                    " triplet(s)";
  std::vector<std::string> why;
  if (t.divergent) why.push_back(std::to_string(t.divergent) + " divergent");
  if (t.oscillatory) why.push_back(std::to_string(t.oscillatory) + " oscillatory");
  if (t.p_out_of_range) why.push_back(std::to_string(t.p_out_of_range) + " p outside the range");
  if (t.no_number) why.push_back(std::to_string(t.no_number) + " without p");
  if (!why.empty()) {
    out += " (";
    for (std::size_t i = 0; i < why.size(); ++i) out += (i ? ", " : "") + why[i];
    out += ")";
  }
  return out + "; least squares: " + t.least_squares;
}

// A grid on which numerics.stall_remedy acted, as the map's hover and the
// table's reason say it.
std::string remedy_note(int from_iteration) {
  return "numerics.stall_remedy relaxed the deferred correction from outer iteration " +
         std::to_string(from_iteration) + " (after a first stall)";
}

constexpr const char* kRemedyLegend = "R: numerics.stall_remedy acted (the deferred correction relaxed after a "
                                      "first stall)";

std::string stability_omitted_note(const StabilityMap& m) {
  if (m.omitted == 0) return {};
  return std::to_string(m.omitted) + " of " + std::to_string(m.series_total) +
         " series not shown (the map shows the series with failures first; every series' grids are in " +
         kStabilityCsv + ").";
}

// The legend's meaning of an outcome in the study's words.
std::string outcome_meaning(const OutcomeStyle& s, const CaseVocabulary& words) {
  if (std::string(s.outcome) == "converged" && words.iterations_counted) return "solved (✓ " + words.iteration + "s)";
  return words.particle_factors || s.any_code == nullptr ? s.meaning : s.any_code;
}

std::string stability_intro(const StabilityMap& m) {
  return "Stability: the outcome of every grid (one row per series, one column per " + m.words.h_symbol +
         ", coarsest on the left). " + std::to_string(m.series_with_failures) + " of " +
         std::to_string(m.series_total) + " series have a failed grid. A solved cell (its solver converged) " +
         (m.words.iterations_counted ? "gives its " + m.words.iteration + "s" : std::string("is marked ✓")) +
         "; hover over a cell for the reason the run gave. The GCI of a triplet is counted usable when its convergence is monotone and its "
         "order p lies in the study's accepted range; least squares is usable when it gave f0.";
}

}  // namespace

Table stability_grid_table(const std::vector<SeriesSummary>& series) {
  Table t;
  const CaseVocabulary words = study_vocabulary(series);  // an external study's declared h
  t.columns = {stab_text("series"), stab_num(words.h_column, words.h_symbol), stab_num("cells"),
               stab_text("outcome"),
               stab_num("outer_iterations", "outer iterations"), stab_text("reason", {}, true),
               stab_text("job_hash")};
  t.columns.back().csv_only = true;
  for (const auto& s : series) {
    std::vector<const GridPoint*> grids;
    for (const GridPoint& g : s.series.grids) grids.push_back(&g);
    std::sort(grids.begin(), grids.end(), [](const auto* a, const auto* b) { return a->delta_star > b->delta_star; });
    for (const GridPoint* g : grids)
      t.rows.push_back({text_cell(s.label), number_cell(g->delta_star, 4),
                        integer_cell(static_cast<long long>(g->nx) * g->ny * g->nz), text_cell(grid_outcome(*g)),
                        words.iterations_counted ? integer_cell(g->iterations) : text_cell(""),
                        text_cell(g->remedy_from_iteration > 0
                                      ? (g->reason.empty() ? "" : g->reason + "; ") + remedy_note(g->remedy_from_iteration)
                                      : g->reason),
                        text_cell(g->job_hash)});
  }
  return t;
}

Table stability_series_table(const StabilityMap& m) {
  Table t;
  t.columns = {stab_text("series"),        stab_num("failed_grids", "failed"),
               stab_num("converged_grids", "converged"), stab_text("stability", {}, true),
               stab_num("gci_triplets", "GCI triplets"), stab_num("gci_usable", "GCI usable"),
               stab_text("least_squares", "least squares", true)};
  for (const auto& r : m.rows)
    t.rows.push_back({text_cell(r.label), integer_cell(r.failures), integer_cell(r.converged), text_cell(r.line),
                      integer_cell(r.methods.triplets), integer_cell(r.methods.gci_usable),
                      text_cell(r.methods.least_squares)});
  return t;
}

Table stability_wide_table(const StabilityMap& m) {
  Table t;
  t.columns.push_back(stab_text("series"));
  for (double h : m.columns)
    t.columns.push_back(stab_text(m.words.h_column + "_" + format_cell_size(h), cell_size_text(m.words, h)));
  for (const auto& r : m.rows) {
    std::vector<Cell> row{text_cell(r.label)};
    for (const auto& c : r.cells) row.push_back(text_cell(stability_cell_text(c, m.words.iterations_counted)));
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string stability_svg(const StabilityMap& m) {
  constexpr int kCellW = 64, kCellH = 20, kTop = 28, kLegendRow = 16;
  std::size_t longest = 6;
  for (const auto& r : m.rows) longest = std::max(longest, r.label.size());
  const int label_w = static_cast<int>(std::min<std::size_t>(longest, 48) * 7 + 12);
  const int cols = static_cast<int>(m.columns.size()), rows = static_cast<int>(m.rows.size());
  const int width = std::max(label_w + cols * kCellW + 8, 420);
  const int map_bottom = kTop + rows * kCellH;
  const bool remedy = std::any_of(m.rows.begin(), m.rows.end(), [](const StabilityRow& r) {
    return std::any_of(r.cells.begin(), r.cells.end(), [](const StabilityCell& c) { return c.remedy_from > 0; });
  });
  const int height =
      map_bottom + 12 + kLegendRow * (static_cast<int>(std::size(kOutcomeStyles)) + (remedy ? 1 : 0)) + 4;
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"stability-map\" width=\"" +
                    std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
                    std::to_string(width) + " " + std::to_string(height) +
                    "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"11\">\n"
                    "<title>Where methods fail: outcome per series and grid</title>\n";
  for (int c = 0; c < cols; ++c)
    out += "<text x=\"" + std::to_string(label_w + c * kCellW + kCellW / 2) + "\" y=\"" + std::to_string(kTop - 8) +
           "\" text-anchor=\"middle\">" + xml_escape(cell_size_text(m.words, m.columns[std::size_t(c)])) +
           "</text>\n";
  for (int r = 0; r < rows; ++r) {
    const StabilityRow& row = m.rows[std::size_t(r)];
    const int y = kTop + r * kCellH;
    std::string label = row.label.size() > 48 ? row.label.substr(0, 45) + "..." : row.label;
    out += "<g><title>" + xml_escape(row.label + ": " + row.line) + "</title><text x=\"4\" y=\"" +
           std::to_string(y + 14) + "\">" + xml_escape(label) + "</text></g>\n";
    for (int c = 0; c < cols; ++c) {
      const StabilityCell& cell = row.cells[std::size_t(c)];
      if (!cell.present) continue;
      const int x = label_w + c * kCellW;
      // Grid outcome words, never the verdict's: a grid is "solved".
      std::string tip = row.label + ", " + cell_size_text(m.words, cell.delta_star) + ": ";
      if (cell.outcome == "converged")
        tip += "solved" + (m.words.iterations_counted
                               ? " in " + std::to_string(cell.iterations) + " " + m.words.iteration + "s"
                               : std::string());
      else
        tip += cell.outcome + (cell.reason.empty() ? std::string() : ": " + cell.reason);
      if (cell.remedy_from > 0) tip += "; " + remedy_note(cell.remedy_from);
      out += "<g class=\"cell outcome-" + cell.outcome + "\"><title>" + xml_escape(tip) + "</title><rect x=\"" +
             std::to_string(x + 1) + "\" y=\"" + std::to_string(y + 1) + "\" width=\"" + std::to_string(kCellW - 2) +
             "\" height=\"" + std::to_string(kCellH - 2) + "\" fill=\"" + outcome_style_of(cell.outcome).fill +
             "\" stroke=\"#888\" stroke-width=\"0.5\"/><text x=\"" + std::to_string(x + kCellW / 2) + "\" y=\"" +
             std::to_string(y + 14) + "\" text-anchor=\"middle\">" + xml_escape(stability_cell_text(cell, m.words.iterations_counted)) + "</text></g>\n";
    }
  }
  int y = map_bottom + 12;
  for (const auto& s : kOutcomeStyles) {
    out += "<rect x=\"4\" y=\"" + std::to_string(y) + "\" width=\"18\" height=\"11\" fill=\"" + s.fill +
           "\" stroke=\"#888\" stroke-width=\"0.5\"/><text x=\"28\" y=\"" + std::to_string(y + 10) + "\">" +
           xml_escape(outcome_meaning(s, m.words)) + "</text>\n";
    y += kLegendRow;
  }
  if (remedy) out += "<text x=\"4\" y=\"" + std::to_string(y + 10) + "\">" + xml_escape(kRemedyLegend) + "</text>\n";
  return out + "</svg>\n";
}

std::string stability_section_html(const ReportContent& c) {
  const StabilityMap m = stability_map(c.series, c.data.p_low, c.data.p_high);
  std::string out = "<section>\n<h2 id=\"stability\">Where methods fail (stability map)</h2>\n";
  out += "<style>@media print { figure.stability-figure { display: none; } }</style>\n";
  out += "<p class=\"note\">" + xml_escape(stability_intro(m)) + "</p>\n";
  if (m.rows.empty()) return out + "<p>No series.</p>\n</section>\n";
  const std::string omitted = stability_omitted_note(m);
  out += "<figure class=\"stability-figure\"><div class=\"scroll\">\n" + stability_svg(m) + "</div>";
  if (!omitted.empty()) out += "<figcaption>" + xml_escape(omitted) + "</figcaption>";
  // The table and its heading are one print block: a landscape page for a
  // wide table, the section's text and per-series list on portrait pages.
  out += "</figure>\n<div class=\"print-block\"><h3 id=\"stability-table\">The map as a table</h3>\n"
         "<div class=\"scroll\">\n" + to_html(stability_wide_table(m)) + "</div></div>\n";
  out += "<h3 id=\"stability-series\">Per series: where it fails, GCI beside least squares</h3>\n<ul>\n";
  for (const auto& r : m.rows)
    out += "<li><strong>" + xml_escape(r.label) + "</strong>: " + xml_escape(r.line) + ". " +
           xml_escape(stability_methods_text(r.methods)) + ".</li>\n";
  out += "</ul>\n";
  if (!omitted.empty()) out += "<p class=\"note\">" + xml_escape(omitted) + "</p>\n";
  out += "<p class=\"note\">CSV: " + std::string(kStabilityCsv) + " (every grid), " + kStabilitySeriesCsv +
         " (per series); the map: " + kStabilitySvg + " (beside this file)</p>\n</section>\n";
  return out;
}

std::string stability_section_markdown(const ReportContent& c) {
  const StabilityMap m = stability_map(c.series, c.data.p_low, c.data.p_high);
  std::string out = "## Where methods fail (stability map)\n\n" + stability_intro(m) + "\n\n";
  if (m.rows.empty()) return out + "No series.\n\n";
  out += to_markdown(stability_wide_table(m)) + "\n";
  for (const auto& r : m.rows) out += "- **" + r.label + "**: " + r.line + ". " + stability_methods_text(r.methods) + ".\n";
  const std::string omitted = stability_omitted_note(m);
  if (!omitted.empty()) out += "\n" + omitted + "\n";
  out += "\nCSV: [" + std::string(kStabilityCsv) + "](" + kStabilityCsv + "), [" + kStabilitySeriesCsv + "](" +
         kStabilitySeriesCsv + ")\n\n";
  return out;
}

void write_stability_files(const ReportContent& c, const std::filesystem::path& dir, ReportFiles& files) {
  files.csv.push_back(dir / kStabilityCsv);
  write_file_atomically(files.csv.back(), csv_by_series(c.series, stability_grid_table));
  const StabilityMap all = stability_map(c.series, c.data.p_low, c.data.p_high, c.series.size());
  files.csv.push_back(dir / kStabilitySeriesCsv);
  write_file_atomically(files.csv.back(), to_csv(stability_series_table(all)));
  // The map as report.html shows it (capped rows); not a chart of files.svg,
  // which get PDF/PNG copies.
  write_file_atomically(dir / kStabilitySvg, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" +
                                              stability_svg(stability_map(c.series, c.data.p_low, c.data.p_high)));
}

}  // namespace gridfree
