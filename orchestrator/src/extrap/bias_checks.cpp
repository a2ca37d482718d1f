// SPDX-License-Identifier: GPL-3.0-or-later
// Declared-order and leave-one-out checks (see bias_checks.h).
#include "extrap/bias_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "extrap/fm_uncertainty.h"
#include "extrap/value_format.h"
#include "extrap/verdict.h"

namespace gridfree {
namespace {

// Numbers that are not values of f (p, P, p/P, factors): 4 significant digits.
std::string g4_bias(double v) { return format_significant(v, 4); }

bool known(const std::optional<double>& v) { return v && std::isfinite(*v); }

// Every U_i at least `factor` |f_ref − f_i| + σ; RDE follows U.
void widen_grids(ExtrapolationResult& out, double f_ref, double factor, double sigma) {
  for (auto& g : out.grids) {
    if (!known(g.u)) continue;
    g.u = std::max(*g.u, factor * std::fabs(f_ref - g.f) + sigma);
    if (*out.f0 != 0) g.rde = *g.u / std::fabs(*out.f0);
  }
}

// Returns the reason the declared order is contradicted, or "".
std::string check_order(const ExtrapolationOptions& opts, const BiasRules& rules, ExtrapolationResult& out) {
  BiasCheck& b = out.bias;
  b.expected_order = opts.expected_order;
  const double declared = *opts.expected_order;
  const double sigma = out.sigma_re.value_or(0.0);
  if (!known(out.p) || *out.p <= 0) {
    b.order_consistent = false;
    return "no positive observed order was found to compare with the declared order " + g4_bias(declared);
  }
  const double q = *out.p / declared;
  const double fs = xing_stern_factor(q);
  b.order_ratio = q;
  b.order_factor = fs;
  b.order_consistent = std::fabs(q - 1.0) <= rules.order_tolerance;
  widen_grids(out, *out.f0, fs, sigma);
  if (out.u0) out.u0 = std::max(*out.u0, fs * std::fabs(*out.f0 - out.grids.front().f) + sigma);
  if (*b.order_consistent) return {};
  return "the observed order p = " + g4_bias(*out.p) + " contradicts the declared order " + g4_bias(declared) +
         " (p/P = " + g4_bias(q) + ", accepted within ±" + g4_bias(rules.order_tolerance) +
         "); the uncertainty uses the factor of safety " + g4_bias(fs) + " of Xing & Stern (2010)";
}

// Returns the reason the leave-one-out fits disagree, or "".
std::string check_leave_one_out(const Series& s, const SubSeriesF0& refit, ExtrapolationResult& out) {
  BiasCheck& b = out.bias;
  const std::size_t n = s.size();
  const Series no_coarsest{std::vector<double>(s.h.begin(), s.h.end() - 1),
                           std::vector<double>(s.f.begin(), s.f.end() - 1)};
  const Series no_finest{std::vector<double>(s.h.begin() + 1, s.h.end()),
                         std::vector<double>(s.f.begin() + 1, s.f.end())};
  b.f0_without_coarsest = refit(no_coarsest);
  b.f0_without_finest = refit(no_finest);
  const double f0 = *out.f0;
  const double u0 = out.u0.value_or(0.0);
  const double sigma = out.sigma_re.value_or(0.0);
  struct Miss {
    std::string name;
    std::optional<double> value;
    double d = 0;
  };
  std::vector<Miss> misses;
  double spread = 0;
  for (const auto& [value, name] : {std::pair{b.f0_without_coarsest, "coarsest"},
                                    std::pair{b.f0_without_finest, "finest"}}) {
    if (!known(value)) {
      misses.push_back({name, std::nullopt, 0.0});
      continue;
    }
    const double d = std::fabs(*value - f0);
    spread = std::max(spread, d);
    widen_grids(out, *value, kMinSafetyFactor, sigma);
    if (d > u0) misses.push_back({name, value, d});
  }
  if (out.u0) out.u0 = u0 + kMinSafetyFactor * spread;
  b.leave_one_out_agree = misses.empty();
  if (misses.empty()) return {};
  // Values of f to the digits f0 ± U₀ is printed with (U₀ as widened here,
  // else the finest grid's U₁), the difference taken between the printed values.
  const std::optional<double> digits_u = f0_digits_u(out.u0, out.grids.front().u);
  const auto val = [&digits_u](double x) { return format_value_for_u(x, digits_u); };
  std::string why;
  for (const auto& m : misses) {
    why += why.empty() ? "" : "; ";
    if (!m.value) {
      why += "the fit without the " + m.name + " grid has no f0";
      continue;
    }
    const double shown_d = std::fabs(rounded_for_u(*m.value, digits_u) - rounded_for_u(f0, digits_u));
    why += "f0 without the " + m.name + " grid (" + val(*m.value) + ") differs from f0 = " + val(f0) + " by " +
           val(shown_d) + " > U₀ = " + val(u0) + " of the fit with every grid";
  }
  return why + " (" + std::to_string(n) + " grids): the series does not agree with itself";
}

}  // namespace

double xing_stern_factor(double q) { return q <= 1.0 ? 2.45 - 0.85 * q : 16.4 * q - 14.8; }

std::vector<std::string> apply_bias_checks(const Series& s, const ExtrapolationOptions& opts,
                                           const SubSeriesF0& refit, ExtrapolationResult& out,
                                           const BiasRules& rules) {
  std::vector<std::string> failed;
  if (!known(out.f0) || out.grids.empty() || (out.method && *out.method == "constant")) return failed;
  if (opts.expected_order) {
    const std::string why = check_order(opts, rules, out);
    if (!why.empty()) failed.push_back(why);
  }
  if (opts.leave_one_out && s.size() >= rules.min_grids_loo) {
    const std::string why = check_leave_one_out(s, refit, out);
    if (!why.empty()) failed.push_back(why);
  }
  return failed;
}

void demote_for_bias(const std::vector<std::string>& failed, const std::vector<double>& h, Verdict& v,
                     const std::string& h_symbol) {
  if (failed.empty()) return;
  if (v.value != "converged") {
    // Before the closing "add the next finer grid" advice.
    v.reasons.insert(v.reasons.empty() ? v.reasons.end() : v.reasons.end() - 1, failed.begin(), failed.end());
    return;
  }
  demote_to_pre_asymptotic(failed, h, v, h_symbol);
}

nlohmann::ordered_json to_ordered_json(const BiasCheck& b) {
  using ojson = nlohmann::ordered_json;
  auto num = [](const std::optional<double>& v) { return known(v) ? ojson(*v) : ojson(nullptr); };
  auto flag = [](const std::optional<bool>& v) { return v ? ojson(*v) : ojson(nullptr); };
  return ojson{{"expected_order", num(b.expected_order)},
               {"order_ratio", num(b.order_ratio)},
               {"order_factor", num(b.order_factor)},
               {"order_consistent", flag(b.order_consistent)},
               {"f0_without_coarsest", num(b.f0_without_coarsest)},
               {"f0_without_finest", num(b.f0_without_finest)},
               {"leave_one_out_agree", flag(b.leave_one_out_agree)}};
}

}  // namespace gridfree
