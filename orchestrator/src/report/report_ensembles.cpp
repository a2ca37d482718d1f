// SPDX-License-Identifier: GPL-3.0-or-later
// The Ensembles section: tables, sentences and rendering (see report_ensembles.h).
#include "report/report_ensembles.h"

#include "report/atomic_file.h"
#include "report/report_content.h"
#include "report/text_format.h"
#include "study/case_vocabulary.h"

namespace gridfree {

namespace {

// The averaging and budget rule; an external study's model form is a
// difference in one of its own factors (report/ensemble_budget.h).
std::string rule_text(const EnsembleSection& e) {
  const CaseVocabulary words = e.configs.empty() ? case_vocabulary(CaseKindId::particle_bed) : e.configs.front().vocabulary;
  const std::string h = words.h_symbol;
  return "f0 is averaged over every instance that has one, whatever its verdict (a configuration where not every "
         "instance converged is flagged); U and RDE at a " + h + " over the instances with a value there. Spread: "
         "sample standard deviation s, standard error s/√n, min–max. Budget at each " + h + ": discretization = "
         "ensemble-mean RDE (a ~95 % bound), model form = the largest relative difference of the ensemble-mean "
         "f0 to a configuration differing only in " +
         words.model_form_rule +
         ", instance spread = s/|mean f0|; the largest of the three dominates.";
}

std::string flag_text(const EnsembleConfig& c) {
  std::string out;
  if (c.flagged())
    out = std::to_string(c.members.size() - static_cast<std::size_t>(c.converged)) + " of " +
          std::to_string(c.members.size()) + " instances not converged";
  if (!c.without_f0.empty()) {
    if (!out.empty()) out += "; ";
    out += "no f0 (left out):";
    for (const auto& n : c.without_f0) out += " " + n;
  }
  if (c.members.size() < 2) {
    if (!out.empty()) out += "; ";
    out += "one instance: no spread";
  }
  return out;
}

}  // namespace

Table ensemble_summary_table(const std::vector<EnsembleConfig>& configs) {
  Table t;
  t.columns = {{"ensemble", "Ensemble"},
               {"configuration", "Configuration"},
               {"instances", "Instances", false, true},
               {"converged", "Converged", false, true},
               {"with_f0", "With f0", false, true},
               {"f0_mean", "Mean f0", false, true},
               {"f0_sd", "s", false, true},
               {"f0_sem", "s/√n", false, true},
               {"f0_min", "Min f0", false, true},
               {"f0_max", "Max f0", false, true},
               {"spread_rel", "s/|mean|", false, true},
               {"cases", "Cases", true},
               {"note", "Note", false, false, true}};
  for (const auto& c : configs) {
    std::string cases;
    for (const auto& n : c.instances) cases += (cases.empty() ? "" : " ") + n;
    const auto& f = c.f0;
    t.rows.push_back({text_cell(c.ensemble), text_cell(c.label().substr(c.ensemble.size() + 2)),
                      integer_cell(static_cast<long long>(c.members.size())), integer_cell(c.converged),
                      integer_cell(f ? f->n : 0), number_cell(f ? std::optional<double>(f->mean) : std::nullopt, 7),
                      number_cell(f ? f->sd : std::nullopt, 3), number_cell(f ? f->sem : std::nullopt, 3),
                      number_cell(f ? std::optional<double>(f->min) : std::nullopt, 7),
                      number_cell(f ? std::optional<double>(f->max) : std::nullopt, 7),
                      percent_cell(f ? f->relative_sd() : std::nullopt), text_cell(cases), text_cell(flag_text(c))});
  }
  return t;
}

Table ensemble_budget_table(const std::vector<EnsembleConfig>& configs, const std::vector<BudgetRow>& rows) {
  Table t;
  t.columns = {{"configuration", "Configuration"},
               {"delta_star",
                (configs.empty() ? case_vocabulary(CaseKindId::particle_bed) : configs.front().vocabulary).h_symbol,
                false, true},
               {"instances_with_u", "Instances", false, true},
               {"u_mean", "Mean U", false, true},
               {"rde_mean", "Discretization (mean RDE)", false, true},
               {"rde_sd", "RDE s", false, true},
               {"rde_min", "RDE min", false, true},
               {"rde_max", "RDE max", false, true},
               {"model_form", "Model form", false, true},
               {"model_form_pair", "Model-form pair"},
               {"instance_spread", "Instance spread", false, true},
               {"dominant", "Largest"}};
  for (const auto& r : rows) {
    const auto& c = configs[r.config];
    const EnsembleGrid* g = nullptr;
    for (const auto& x : c.grids)
      if (x.delta_star == r.delta_star) g = &x;
    const auto& rs = g ? g->rde_stats : std::nullopt;
    const auto& us = g ? g->u_stats : std::nullopt;
    t.rows.push_back({text_cell(c.label()), number_cell(r.delta_star, 4), integer_cell(rs ? rs->n : 0),
                      number_cell(us ? std::optional<double>(us->mean) : std::nullopt, 3),
                      percent_cell(r.discretization), percent_cell(rs ? rs->sd : std::nullopt),
                      percent_cell(rs ? std::optional<double>(rs->min) : std::nullopt),
                      percent_cell(rs ? std::optional<double>(rs->max) : std::nullopt), percent_cell(r.model_form),
                      text_cell(r.model_form_pair), percent_cell(r.spread), text_cell(r.dominant)});
  }
  return t;
}

EnsembleSection ensemble_section(const std::vector<SeriesSummary>& series,
                                 const std::map<std::string, std::vector<std::string>>& ensembles) {
  EnsembleSection s;
  s.configs = ensemble_configs(series, ensembles);
  if (s.configs.empty()) return s;
  s.model_form = model_form_differences(s.configs);
  s.budget = budget_rows(s.configs, s.model_form);
  s.sentences = budget_sentences(s.configs, s.budget);
  s.summary_table = ensemble_summary_table(s.configs);
  s.budget_table = ensemble_budget_table(s.configs, s.budget);
  for (const auto& [name, cases] : ensembles) {
    Chart chart = ensemble_budget_chart(name, s.configs, s.budget);
    s.charts.push_back({"budget_" + slugify(name) + ".svg",
                        "Uncertainty budget of ensemble " + name +
                            ": discretization (ensemble-mean RDE, bars = s over instances) against model-form "
                            "differences and the instance-to-instance spread.",
                        chart, {}});
  }
  return s;
}

void write_ensemble_files(const EnsembleSection& e, const std::filesystem::path& out_dir, ReportFiles& files) {
  if (e.empty()) return;
  for (const auto& [file, table] : {std::pair{"ensembles.csv", &e.summary_table}, std::pair{"budget.csv", &e.budget_table}}) {
    files.csv.push_back(out_dir / file);
    write_file_atomically(files.csv.back(), to_csv(*table));
  }
  for (const auto& chart : e.charts) {
    files.svg.push_back(out_dir / chart.file);
    write_file_atomically(files.svg.back(), render_svg_file(chart.chart));
  }
}

std::string ensembles_markdown(const ReportContent& c) {
  const EnsembleSection& e = c.ensembles;
  if (e.empty()) return "";
  std::string out = "## Ensembles and uncertainty budget\n\n" + rule_text(e) + "\n\n";
  out += to_markdown(e.summary_table) + "\nCSV: [ensembles.csv](ensembles.csv)\n\n";
  for (const auto& s : e.sentences) out += "- " + s + "\n";
  out += "\n";
  for (const auto& chart : e.charts)
    out += "![" + md_cell(chart.chart.title) + "](" + chart.file + ")\n\n" + chart.caption + "\n\n";
  out += to_markdown(e.budget_table) + "\nCSV: [budget.csv](budget.csv)\n\n";
  return out;
}

std::string ensembles_html(const ReportContent& c) {
  const EnsembleSection& e = c.ensembles;
  if (e.empty()) return "";
  std::string out = "<h2 id=\"ensembles\">Ensembles and uncertainty budget</h2>\n<p class=\"note\">" +
                    xml_escape(rule_text(e)) + "</p>\n";
  out += "<div class=\"scroll\">\n" + to_html(e.summary_table) + "</div>\n";
  out += "<p class=\"note\">CSV: ensembles.csv (beside this file)</p>\n<ul>\n";
  for (const auto& s : e.sentences) out += "<li>" + xml_escape(s) + "</li>\n";
  out += "</ul>\n<div class=\"charts\">\n";
  for (const auto& chart : e.charts)
    out += "<figure id=\"" + xml_escape(slugify(chart.file)) + "\">\n<div class=\"chart-wide\">" +
           render_svg(chart.chart) + "</div><div class=\"chart-narrow\">" + render_svg(narrow_chart(chart.chart)) +
           "</div><figcaption>" + xml_escape(chart.caption) + " File: " + xml_escape(chart.file) +
           "</figcaption>\n</figure>\n";
  out += "</div>\n<div class=\"scroll\">\n" + to_html(e.budget_table) + "</div>\n";
  out += "<p class=\"note\">CSV: budget.csv (beside this file)</p>\n";
  return out;
}

}  // namespace gridfree
