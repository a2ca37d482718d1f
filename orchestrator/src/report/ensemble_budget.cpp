// SPDX-License-Identifier: GPL-3.0-or-later
// Uncertainty budget of an ensemble (see ensemble_budget.h).
#include "report/ensemble_budget.h"

#include <algorithm>

#include "report/differences.h"
#include "extrap/value_format.h"
#include "report/text_format.h"
#include "study/case_vocabulary.h"

namespace gridfree {

namespace {

// Two configurations of one ensemble and quantity that differ in exactly
// one factor, a model-form one of their case kind (CaseVocabulary::
// model_form_factors; any factor when it names none): that factor and the
// two levels.
std::optional<ModelFormDifference> model_form_difference(const EnsembleConfig& x, const EnsembleConfig& y) {
  if (x.ensemble != y.ensemble || x.quantity != y.quantity || x.factors.size() != y.factors.size())
    return std::nullopt;
  std::optional<ModelFormDifference> out;
  for (std::size_t k = 0; k < x.factors.size(); ++k) {
    const auto& [name, level] = x.factors[k];
    if (y.factors[k].first != name) return std::nullopt;
    if (y.factors[k].second == level) continue;
    if (out) return std::nullopt;  // a second factor differs
    out = ModelFormDifference{};
    out->factor = name;
    out->value_a = level;
    out->value_b = y.factors[k].second;
  }
  const auto& model = x.vocabulary.model_form_factors;
  if (out && !model.empty() && std::find(model.begin(), model.end(), out->factor) == model.end()) return std::nullopt;
  return out;
}

}  // namespace

std::vector<ModelFormDifference> model_form_differences(const std::vector<EnsembleConfig>& configs) {
  std::vector<ModelFormDifference> out;
  for (std::size_t a = 0; a < configs.size(); ++a) {
    for (std::size_t b = a + 1; b < configs.size(); ++b) {
      const auto& x = configs[a];
      const auto& y = configs[b];
      if (auto d = model_form_difference(x, y)) {
        d->a = a;
        d->b = b;
        if (x.f0 && y.f0) d->relative = relative_difference(x.f0->mean, y.f0->mean);
        out.push_back(*d);
      }
    }
  }
  return out;
}

std::string dominant_source(const std::optional<double>& d, const std::optional<double>& m,
                            const std::optional<double>& s) {
  std::string best;
  double value = -1;
  for (const auto& [name, v] : {std::pair{"discretization", d}, std::pair{"model form", m}, std::pair{"instance spread", s}}) {
    if (v && *v > value) {
      value = *v;
      best = name;
    }
  }
  return best;
}

std::vector<BudgetRow> budget_rows(const std::vector<EnsembleConfig>& configs,
                                   const std::vector<ModelFormDifference>& differences) {
  std::vector<BudgetRow> out;
  for (std::size_t c = 0; c < configs.size(); ++c) {
    std::optional<double> m;
    std::string pair;
    for (const auto& d : differences) {
      if ((d.a != c && d.b != c) || !d.relative) continue;
      if (!m || *d.relative > *m) {
        m = d.relative;
        pair = d.factor + " " + d.value_a + " vs " + d.value_b;
      }
    }
    const auto s = configs[c].f0 ? configs[c].f0->relative_sd() : std::nullopt;
    for (const auto& g : configs[c].grids) {
      BudgetRow r;
      r.config = c;
      r.delta_star = g.delta_star;
      if (g.rde_stats) r.discretization = g.rde_stats->mean;
      r.model_form = m;
      r.model_form_pair = pair;
      r.spread = s;
      r.dominant = dominant_source(r.discretization, r.model_form, r.spread);
      out.push_back(r);
    }
  }
  return out;
}

namespace {

std::string numbers(const BudgetRow& r) {
  std::string out;
  auto add = [&](const char* name, const std::optional<double>& v) {
    if (!v) return;
    if (!out.empty()) out += ", ";
    out += std::string(name) + " " + format_percent(v, 2);
  };
  add("discretization", r.discretization);
  add("model form", r.model_form);
  add("instance spread", r.spread);
  return out;
}

}  // namespace

std::vector<std::string> budget_sentences(const std::vector<EnsembleConfig>& configs,
                                          const std::vector<BudgetRow>& rows) {
  std::vector<std::string> out;
  for (std::size_t c = 0; c < configs.size(); ++c) {
    std::vector<const BudgetRow*> mine;
    for (const auto& r : rows)
      if (r.config == c && !r.dominant.empty()) mine.push_back(&r);
    if (mine.empty()) continue;
    std::string text = configs[c].label() + ": ";
    std::size_t i = 0;
    bool first = true;
    while (i < mine.size()) {
      std::size_t j = i;
      while (j + 1 < mine.size() && mine[j + 1]->dominant == mine[i]->dominant) ++j;
      if (!first) text += "; ";
      first = false;
      const std::string h = configs[c].vocabulary.h_symbol + " ";
      const std::string range = i == j ? "at " + h + format_cell_size(mine[i]->delta_star)
                                       : "for " + h + format_cell_size(mine[i]->delta_star) + "–" +
                                             format_cell_size(mine[j]->delta_star);
      text += mine[i]->dominant + " dominates " + range + " (at " + h + format_cell_size(mine[i]->delta_star) + ": " +
              numbers(*mine[i]) + ")";
      i = j + 1;
    }
    if (!mine.front()->model_form_pair.empty()) text += "; model form = " + mine.front()->model_form_pair;
    out.push_back(text + ".");
  }
  return out;
}

}  // namespace gridfree
