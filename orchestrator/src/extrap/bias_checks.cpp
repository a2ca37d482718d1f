// SPDX-License-Identifier: GPL-3.0-or-later
// Declared-order and leave-one-out checks (see bias_checks.h).
#include "extrap/bias_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "extrap/fm_uncertainty.h"
#include "extrap/verdict.h"

namespace gridfree {
namespace {

std::string g4_bias(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

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
  std::string why;
  bool agree = true;
  double spread = 0;
  for (const auto& [value, name] : {std::pair{b.f0_without_coarsest, "coarsest"},
                                    std::pair{b.f0_without_finest, "finest"}}) {
    if (!known(value)) {
      agree = false;
      why += std::string(why.empty() ? "" : "; ") + "the fit without the " + name + " grid has no f0";
      continue;
    }
    const double d = std::fabs(*value - f0);
    spread = std::max(spread, d);
    widen_grids(out, *value, kMinSafetyFactor, sigma);
    if (d > u0) {
      agree = false;
      why += std::string(why.empty() ? "" : "; ") + "f0 without the " + name + " grid (" + g4_bias(*value) +
             ") differs from f0 = " + g4_bias(f0) + " by " + g4_bias(d) + " > U₀ = " + g4_bias(u0);
    }
  }
  if (out.u0) out.u0 = u0 + kMinSafetyFactor * spread;
  b.leave_one_out_agree = agree;
  if (agree) return {};
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

void demote_for_bias(const std::vector<std::string>& failed, const std::vector<double>& h, Verdict& v) {
  if (failed.empty()) return;
  if (v.value != "converged") {
    // Before the closing "add the next finer grid" advice.
    v.reasons.insert(v.reasons.empty() ? v.reasons.end() : v.reasons.end() - 1, failed.begin(), failed.end());
    return;
  }
  demote_to_pre_asymptotic(failed, h, v);
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
