// SPDX-License-Identifier: GPL-3.0-or-later
// The answer and the attention list that open the report (see first_screen.h).
#include "report/first_screen.h"

#include <algorithm>
#include <map>

#include "extrap/value_format.h"
#include "report/report_alignment.h"
#include "report/report_layout.h"
#include "report/series_concerns.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {
namespace {

constexpr const char* kVerdictOrder[] = {"converged", "pre-asymptotic", "unreliable", "insufficient_grids"};

std::string verdict_counts(const std::vector<SeriesSummary>& series) {
  std::map<std::string, int> n;
  std::vector<std::string> order(std::begin(kVerdictOrder), std::end(kVerdictOrder));
  int incomplete = 0;
  for (const auto& s : series) {
    const std::string v = s.verdict.empty() ? "no verdict" : s.verdict;
    if (std::find(order.begin(), order.end(), v) == order.end()) order.push_back(v);
    ++n[v];
    if (s.incomplete) ++incomplete;
  }
  std::string out = std::to_string(series.size()) + " series:";
  bool first = true;
  for (const auto& v : order) {
    if (!n[v]) continue;
    out += (first ? " " : ", ") + std::to_string(n[v]) + " " + v;
    first = false;
  }
  if (incomplete) out += " (" + std::to_string(incomplete) + " with grids still to run)";
  return out;
}

AnswerRow answer_row(const SeriesSummary& s, std::size_t i) {
  AnswerRow r{i, s.label, s.verdict.empty() ? "—" : s.verdict, "—", "—"};
  const auto f0 = s.f0();
  const ExtrapolatedGrid* finest =
      s.extrapolation && !s.extrapolation->grids.empty() ? &s.extrapolation->grids.front() : nullptr;
  const std::optional<double> u1 = finest ? finest->u : std::nullopt;
  if (f0) {
    const auto u0 = s.extrapolation->u0;
    r.f0 = u0 ? format_value_u(*f0, u0) : format_value_for_u(*f0, u1) + " (no U₀)";
  }
  if (finest)
    r.f1 = format_value_u(finest->f, u1) + " at " + cell_size_text(series_vocabulary(s.series), finest->h);
  return r;
}

std::string series_href(const ReportContent& c, std::size_t i) {
  return c.layout == ReportLayout::summary ? series_page_file(c, i) : "#" + verdict_anchor(c.series[i].label);
}

}  // namespace

std::string verdict_anchor(const std::string& label) { return "v-" + slugify(label); }

FirstScreen first_screen(const ReportContent& c) {
  FirstScreen out;
  out.counts = verdict_counts(c.series);
  for (std::size_t i = 0; i < c.series.size() && out.rows.size() < kAnswerRows; ++i)
    out.rows.push_back(answer_row(c.series[i], i));
  out.more_series = c.series.size() - out.rows.size();
  const auto concerns = series_concerns(c.series, c.data.p_low, c.data.p_high);
  out.attention_total = concerns.size();
  const std::size_t shown = c.layout == ReportLayout::summary ? kShownWarnings : concerns.size();
  for (std::size_t k = 0; k < concerns.size() && k < shown; ++k) {
    std::string text;
    for (const auto& t : concerns[k].concerns) text += (text.empty() ? "" : "; ") + t;
    out.attention.push_back({concerns[k].series, c.series[concerns[k].series].label, text});
  }
  for (auto& w : alignment_warnings(c.alignment)) out.study_notes.push_back(std::move(w));
  int pending = 0;
  for (const auto& s : c.series) pending += s.pending;
  if (pending)
    out.study_notes.push_back(std::to_string(pending) + " grid(s) still to run: the numbers of their series may change.");
  return out;
}

std::string first_screen_html(const ReportContent& c) {
  const FirstScreen f = first_screen(c);
  std::string out = "<section class=\"answer\" id=\"answer\">\n<p class=\"counts\"><strong>" +
                    xml_escape(f.counts) + "</strong></p>\n";
  if (!f.rows.empty()) {
    out += "<div class=\"scroll\"><table class=\"data answer-table\">\n<thead><tr><th>series</th><th>f0 ± U₀</th>"
           "<th>verdict</th><th>finest f₁ ± U₁</th></tr></thead>\n<tbody>\n";
    for (const auto& r : f.rows)
      out += "<tr><td class=\"text\"><a href=\"" + xml_escape(series_href(c, r.series)) + "\">" +
             xml_escape(r.label) + "</a></td><td class=\"num\">" + xml_escape(r.f0) + "</td><td class=\"text\">" +
             xml_escape(r.verdict) + "</td><td class=\"num\">" + xml_escape(r.f1) + "</td></tr>\n";
    out += "</tbody></table></div>\n";
  }
  if (f.more_series)
    out += "<p class=\"note\">… and " + std::to_string(f.more_series) +
           " more series: every one in <a href=\"#series\">the series table</a>, which filters.</p>\n";
  out += "</section>\n";
  if (f.attention.empty() && f.study_notes.empty()) return out;
  out += "<div class=\"attention\" id=\"attention\"><strong>Attention: " + std::to_string(f.attention_total) + " of " +
         std::to_string(c.series.size()) + " series need a look</strong>, worst first<ul>\n";
  for (const auto& a : f.attention)
    out += "<li><a href=\"" + xml_escape(series_href(c, a.series)) + "\">" + xml_escape(a.label) + "</a>: " +
           xml_escape(a.text) + "</li>\n";
  if (f.attention.size() < f.attention_total)
    out += "<li class=\"more\">… and " + std::to_string(f.attention_total - f.attention.size()) +
           " more: <a href=\"#series\" data-filter=\"attention:yes\">all " + std::to_string(f.attention_total) +
           " in the series table</a> (filter <code>attention:yes</code>; <code>failed&gt;0</code> for failed "
           "grids).</li>\n";
  for (const auto& n : f.study_notes) out += "<li>" + xml_escape(n) + "</li>\n";
  out += "</ul></div>\n";
  return out;
}

std::string first_screen_markdown(const ReportContent& c) {
  const FirstScreen f = first_screen(c);
  std::string out = "**" + f.counts + "**\n\n";
  if (!f.rows.empty()) {
    out += "| series | f0 ± U₀ | verdict | finest f₁ ± U₁ |\n|---|---:|---|---:|\n";
    for (const auto& r : f.rows)
      out += "| " + (c.layout == ReportLayout::summary ? "[" + md_cell(r.label) + "](" + series_page_file(c, r.series) + ")"
                                                        : md_cell(r.label)) +
             " | " + md_cell(r.f0) + " | " + md_cell(r.verdict) + " | " + md_cell(r.f1) +
             " |\n";
    out += "\n";
  }
  if (f.more_series) out += "… and " + std::to_string(f.more_series) + " more series: every one in the series table.\n\n";
  if (f.attention.empty() && f.study_notes.empty()) return out;
  out += "**Attention: " + std::to_string(f.attention_total) + " of " + std::to_string(c.series.size()) +
         " series need a look**, worst first:\n\n";
  for (const auto& a : f.attention)
    out += "- " + (c.layout == ReportLayout::summary ? "[" + a.label + "](" + series_page_file(c, a.series) + ")" : a.label) +
           ": " + a.text + "\n";
  if (f.attention.size() < f.attention_total)
    out += "- … and " + std::to_string(f.attention_total - f.attention.size()) +
           " more (series.csv: the `attention` column; each series' page)\n";
  for (const auto& n : f.study_notes) out += "- " + n + "\n";
  return out + "\n";
}

}  // namespace gridfree
