// SPDX-License-Identifier: GPL-3.0-or-later
// The budget chart of one ensemble (see report_ensembles.h): x = Δ*, y = %.
//   one curve per configuration: ensemble-mean RDE, error bars = its sample sd
//   dashed lines: each configuration's instance spread (its colour) and each
//   model-form difference (black); constant in Δ*: they are differences of
//   extrapolated values
#include "report/report_ensembles.h"

#include <algorithm>
#include <cmath>

#include "report/text_format.h"
#include "study/case_vocabulary.h"

namespace gridfree {

constexpr int kModelFormColour = 6;  // black; configurations take palette 0, 1, ...

Chart ensemble_budget_chart(const std::string& ensemble, const std::vector<EnsembleConfig>& configs,
                            const std::vector<BudgetRow>& rows) {
  Chart chart;
  chart.id = "budget-" + slugify(ensemble);
  chart.title = "Uncertainty budget, ensemble " + ensemble;
  chart.subtitle = "discretization (mean RDE) vs model form and instance spread";
  const auto first = std::find_if(configs.begin(), configs.end(),
                                  [&](const EnsembleConfig& c) { return c.ensemble == ensemble; });
  const CaseVocabulary words = first != configs.end() ? first->vocabulary : case_vocabulary(CaseKindId::particle_bed);
  chart.x = {words.h_meaning, AxisScale::linear, 0.0, std::nullopt};
  chart.y = {"relative size (%)", AxisScale::linear, 0.0, std::nullopt};
  int k = 0;
  for (std::size_t c = 0; c < configs.size(); ++c) {
    if (configs[c].ensemble != ensemble) continue;
    const std::string name = configs[c].label().substr(ensemble.size() + 2);
    ChartSeries s{"RDE " + name, {}, {}, {}, marker_for(k), true, false, false, k};
    std::optional<double> model, spread;
    std::string pair;
    for (const auto& r : rows) {
      if (r.config != c) continue;
      model = r.model_form;
      spread = r.spread;
      pair = r.model_form_pair;
      if (!r.discretization) continue;
      s.x.push_back(r.delta_star);
      s.y.push_back(*r.discretization * 100.0);
      const EnsembleGrid* g = nullptr;
      for (const auto& x : configs[c].grids)
        if (x.delta_star == r.delta_star) g = &x;
      s.y_error.push_back(g && g->rde_stats && g->rde_stats->sd ? *g->rde_stats->sd * 100.0 : NAN);
    }
    if (!s.x.empty()) chart.series.push_back(s);
    if (spread) chart.hlines.push_back({*spread * 100.0, "instance spread s/|mean| " + name, k, true});
    // A model-form pair is the same line for both of its configurations: drawn
    // once, in black, so that no configuration's spread line shares its style.
    const std::string model_label = "model form (" + pair + ")";
    const bool drawn = std::any_of(chart.hlines.begin(), chart.hlines.end(),
                                   [&](const ChartHLine& l) { return l.label == model_label; });
    if (model && !drawn) chart.hlines.push_back({*model * 100.0, model_label, kModelFormColour, true});
    ++k;
  }
  if (chart.series.empty() && chart.hlines.empty())
    chart.note = "No configuration of this ensemble has an uncertainty yet (needs 4 converged grids).";
  return chart;
}

}  // namespace gridfree
