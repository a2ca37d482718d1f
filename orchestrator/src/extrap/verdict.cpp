// SPDX-License-Identifier: GPL-3.0-or-later
// Verdict rules of docs/EXTRAPOLATION.md "Verdicts" (see verdict.h).
#include "extrap/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "extrap/value_format.h"

namespace gridfree {
namespace {

// Numbers that are not values of f (p, σ_RE/R_f, k, ratios): 4 significant
// digits; RDE as the report prints it; a rule's threshold without trailing zeros.
std::string g4(double v) { return format_significant(v, 4); }

std::string percent(double v) { return format_percent_fixed(v); }

std::string threshold_percent(double v) { return format_significant(100.0 * v, 3) + "%"; }

bool finite(const std::optional<double>& v) { return v && std::isfinite(*v); }

// Where f0 lies relative to the data: inside [min f, max f], or how far beyond
// the smallest/largest value (then within the envelope of k R_f, since the
// sentence is only used when the envelope rule passed). Values and the
// distance are quoted to the decimal `u` supports, the distance taken between
// the rounded values, so the sentence agrees with the printed f0 ± U.
std::string envelope_sentence(double f0, double lo, double hi, double range, double k,
                              const std::optional<double>& u) {
  const auto q = [&](double v) { return format_value_for_u(v, u); };
  if (f0 >= lo && f0 <= hi) return "f0 lies within the data range [" + q(lo) + ", " + q(hi) + "]";
  const bool above = f0 > hi;
  const double d = above ? rounded_for_u(f0, u) - rounded_for_u(hi, u) : rounded_for_u(lo, u) - rounded_for_u(f0, u);
  std::string s = "f0 lies " + q(d) + (above ? " above the largest" : " below the smallest") + " value " +
                  q(above ? hi : lo);
  if (range > 0) s += " (" + g4(d / range) + " R_f), within the envelope of " + g4(k) + " R_f";
  return s;
}

// +1 when every grid-to-grid difference f_{i+1} − f_i (h ascending) is
// positive, −1 when every one is negative, 0 otherwise or with fewer than
// `min_steps` differences.
int monotone_sign(const std::vector<double>& f, std::size_t min_steps) {
  if (f.size() < min_steps + 1) return 0;
  int sign = 0;
  for (std::size_t i = 1; i < f.size(); ++i) {
    const double d = f[i] - f[i - 1];
    const int s = d > 0 ? 1 : (d < 0 ? -1 : 0);
    if (s == 0 || (sign != 0 && s != sign)) return 0;
    sign = s;
  }
  return sign;
}

std::string next_grid_advice(const Verdict& v, double r, const std::string& h_symbol) {
  if (!v.next_h) return {};
  return "add the next finer grid " + h_symbol + " = " + format_cell_size(*v.next_h) +
         " (the series' mean refinement ratio " + g4(r) + ")";
}

}  // namespace

double mean_refinement_ratio(const std::vector<double>& h) {
  if (h.size() < 2 || !(h.front() > 0)) return 1.0;
  return std::pow(h.back() / h.front(), 1.0 / static_cast<double>(h.size() - 1));
}

Verdict verdict_without_fit(int n_grids, const std::string& why) {
  Verdict v;
  v.checks.n_grids = n_grids;
  v.checks.dof = std::max(0, n_grids - 3);
  if (n_grids < 4) {
    v.value = "insufficient_grids";
    v.reasons.push_back(std::to_string(n_grids) +
                        " converged grid(s): the least-squares fit needs at least 4, a converged verdict 5");
  } else {
    v.value = "unreliable";
    v.reasons.push_back(why);
  }
  return v;
}

void demote_to_pre_asymptotic(std::vector<std::string> why, const std::vector<double>& h, Verdict& v,
                              const std::string& h_symbol) {
  v.value = "pre-asymptotic";
  const double r = mean_refinement_ratio(h);
  v.next_h = h.front() / r;
  why.push_back(next_grid_advice(v, r, h_symbol));
  v.reasons = std::move(why);
}

Verdict judge(const ExtrapolationResult& r, const ExtrapolationOptions& opts, const VerdictRules& rules) {
  const int n = static_cast<int>(r.grids.size());
  std::vector<double> h, f;
  for (const auto& g : r.grids) {
    h.push_back(g.h);
    f.push_back(g.f);
  }
  const double ratio = mean_refinement_ratio(h);
  const std::optional<double> next_h = n >= 2 ? std::optional<double>(h.front() / ratio) : std::nullopt;

  if (r.status == "insufficient_grids" || n < 4) {
    Verdict v = verdict_without_fit(n, {});
    v.next_h = next_h;
    if (next_h) v.reasons.push_back(next_grid_advice(v, ratio, opts.h_symbol));
    return v;
  }

  Verdict v;
  v.next_h = next_h;
  VerdictChecks& c = v.checks;
  c.n_grids = n;
  c.dof = n - 3;
  c.p = r.p;
  c.sigma_over_range = r.sigma_over_range;
  if (finite(r.grids.front().rde)) c.rde_finest = r.grids.front().rde;

  if (r.method && *r.method == "constant") {
    v.value = "converged";
    v.reasons.push_back("f is the same on every grid: no discretization error is visible");
    c.order_in_range = c.good_fit = c.inside_envelope = true;
    v.next_h.reset();
    return v;
  }

  const auto [lo_it, hi_it] = std::minmax_element(f.begin(), f.end());
  // Values of f are quoted to the digits f0 ± U is printed with
  // (value_format.h), so a sentence and the value beside it agree.
  const std::optional<double> digits_u = f0_digits_u(r.u0, r.grids.front().u);
  const auto val = [&digits_u](double x) { return format_value_for_u(x, digits_u); };
  if (finite(r.data_range)) {
    c.envelope_low = *lo_it - rules.envelope_k * *r.data_range;
    c.envelope_high = *hi_it + rules.envelope_k * *r.data_range;
  }
  c.inside_envelope = finite(r.f0) && c.envelope_low && *r.f0 >= *c.envelope_low && *r.f0 <= *c.envelope_high;
  c.order_in_range = finite(r.p) && *r.p >= opts.p_low && *r.p <= opts.p_high;
  // With fewer than min_dof degrees of freedom σ_RE rests on too few
  // residuals to judge the fit: never claimed as good.
  c.good_fit = finite(r.sigma_over_range) && *r.sigma_over_range < 1.0 && c.dof >= rules.min_dof;
  // Monotone data: f0 must lie ahead of the finest value along the trend.
  const int trend = monotone_sign(f, 3);  // +1: f decreases with refinement
  c.monotone = trend != 0;
  c.behind_trend = finite(r.f0) && ((trend > 0 && *r.f0 > f.front()) || (trend < 0 && *r.f0 < f.front()));

  // Rules that make the extrapolation unreliable.
  std::vector<std::string> unreliable;
  if (!finite(r.f0)) unreliable.push_back("no extrapolated value f0 could be computed");
  if (c.dof < rules.min_dof)
    unreliable.push_back(std::to_string(n) + " grids leave " + std::to_string(c.dof) +
                         " degree(s) of freedom for the 3-parameter fit; at least " +
                         std::to_string(rules.min_dof) + " are needed (" +
                         std::to_string(3 + rules.min_dof) + " grids)" +
                         (finite(r.sigma_over_range) ? "; the fit (σ_RE/R_f = " + g4(*r.sigma_over_range) +
                                                           ") cannot be judged"
                                                     : std::string()));
  if (finite(r.f0) && c.envelope_low && !c.inside_envelope)
    unreliable.push_back("f0 = " + val(*r.f0) + " lies outside the data envelope [" + val(*c.envelope_low) + ", " +
                         val(*c.envelope_high) + "] (min f − " + g4(rules.envelope_k) + " R_f, max f + " +
                         g4(rules.envelope_k) + " R_f): the fit extrapolates far beyond what the grids show");
  if (c.behind_trend)
    unreliable.push_back("the data " + std::string(trend > 0 ? "fall" : "rise") + " with every refinement (" +
                         std::to_string(f.size() - 1) + " grid-to-grid differences of one sign) but f0 = " +
                         val(*r.f0) + " lies " + (trend > 0 ? "above" : "below") + " the finest value " +
                         val(f.front()) + ": the fit turns back against the trend");
  if (c.rde_finest && *c.rde_finest > rules.rde_unreliable)
    unreliable.push_back("the finest grid's RDE " + percent(*c.rde_finest) + " exceeds " +
                         threshold_percent(rules.rde_unreliable));

  // Conditions a converged series must also meet.
  std::vector<std::string> missing;
  if (!c.order_in_range)
    missing.push_back(finite(r.p) ? "observed order p = " + g4(*r.p) + " is outside the accepted range [" +
                                        g4(opts.p_low) + ", " + g4(opts.p_high) + "]"
                                  : "no observed order p was found (the power law has no interior minimum)");
  if (!c.good_fit && c.dof >= rules.min_dof)
    missing.push_back(finite(r.sigma_over_range)
                          ? "the fit does not describe the data: σ_RE/R_f = " + g4(*r.sigma_over_range) + " ≥ 1"
                          : "the fit quality σ_RE/R_f is undefined");
  if (c.rde_finest && *c.rde_finest > rules.rde_converged && *c.rde_finest <= rules.rde_unreliable)
    missing.push_back("the finest grid's RDE " + percent(*c.rde_finest) + " exceeds " +
                      threshold_percent(rules.rde_converged));
  if (!c.rde_finest && finite(r.f0)) missing.push_back("the finest grid's RDE is undefined (f0 = 0)");

  if (!unreliable.empty()) {
    v.value = "unreliable";
    v.reasons = unreliable;
    v.reasons.insert(v.reasons.end(), missing.begin(), missing.end());
  } else if (!missing.empty()) {
    v.value = "pre-asymptotic";
    v.reasons = missing;
  } else {
    v.value = "converged";
    v.reasons.push_back("p = " + g4(*r.p) + " in [" + g4(opts.p_low) + ", " + g4(opts.p_high) +
                        "], σ_RE/R_f = " + g4(*r.sigma_over_range) + " < 1, " +
                        envelope_sentence(*r.f0, *lo_it, *hi_it, r.data_range.value_or(0.0), rules.envelope_k,
                                          digits_u) +
                        ", " +
                        std::to_string(c.dof) + " degrees of freedom, finest-grid RDE " +
                        percent(*c.rde_finest) + " ≤ " + threshold_percent(rules.rde_converged));
    v.next_h.reset();
    return v;
  }
  v.reasons.push_back(next_grid_advice(v, ratio, opts.h_symbol) +
                      (c.dof < rules.min_dof ? " or more grids in the same range" : ""));
  return v;
}

}  // namespace gridfree
