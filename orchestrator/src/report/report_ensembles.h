// SPDX-License-Identifier: GPL-3.0-or-later
// The report's "Ensembles" section (docs/EXTRAPOLATION.md "Ensembles"):
//   ensembles.csv     per ensemble and configuration: instances, converged
//                     verdicts, ensemble-mean f0, sample sd, standard error,
//                     min–max, relative spread
//   budget.csv        per configuration and Δ*: ensemble-mean U and RDE (sd,
//                     min–max), the model-form difference, the instance
//                     spread and which of the three dominates
//   budget_<ens>.svg  the budget chart: ensemble-mean RDE per configuration
//                     vs Δ* (bars: sd over instances), model-form differences
//                     and instance spreads as horizontal lines
// plus one sentence per configuration saying which source dominates where.
// A study without ensembles has an empty section (nothing rendered).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "report/ensemble_budget.h"
#include "report/ensemble_stats.h"
#include "report/report.h"
#include "report/report_charts.h"
#include "report/table.h"

namespace gridfree {

struct ReportContent;

struct EnsembleSection {
  std::vector<EnsembleConfig> configs;
  std::vector<ModelFormDifference> model_form;
  std::vector<BudgetRow> budget;
  std::vector<std::string> sentences;
  Table summary_table, budget_table;   // ensembles.csv, budget.csv
  std::vector<NamedChart> charts;      // one budget chart per ensemble
  bool empty() const { return configs.empty(); }
};

EnsembleSection ensemble_section(const std::vector<SeriesSummary>& series,
                                 const std::map<std::string, std::vector<std::string>>& ensembles);

Table ensemble_summary_table(const std::vector<EnsembleConfig>& configs);
Table ensemble_budget_table(const std::vector<EnsembleConfig>& configs, const std::vector<BudgetRow>& rows);
Chart ensemble_budget_chart(const std::string& ensemble, const std::vector<EnsembleConfig>& configs,
                            const std::vector<BudgetRow>& rows);

// Writes ensembles.csv, budget.csv and the budget charts (SVG) into out_dir
// and lists them in files; nothing without ensembles.
void write_ensemble_files(const EnsembleSection& section, const std::filesystem::path& out_dir, ReportFiles& files);

// The section in Markdown / HTML ("" when there are no ensembles).
std::string ensembles_markdown(const ReportContent& content);
std::string ensembles_html(const ReportContent& content);

}  // namespace gridfree
