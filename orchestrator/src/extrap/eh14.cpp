// SPDX-License-Identifier: GPL-3.0-or-later
// Eça & Hoekstra (2014) uncertainty procedure, Appendix A (see eh14.h).
#include "extrap/eh14.h"

#include <cmath>
#include <string>
#include <vector>

#include "extrap/mixed_fit.h"
#include "extrap/power_fit.h"

namespace gridfree {
namespace {

// EH14's theoretical order: fits with p ≥ 2 fall back to fixed orders.
constexpr double kTheoreticalOrder = 2.0;

// A candidate error estimator: one fit in one weighting.
struct Candidate {
  std::string name;  // power | first | second | mixed
  bool weighted = false;
  double f0 = 0, sigma = 0;
  std::vector<double> fhat;
};

// σ comparisons: NaN never wins; on a tie the earlier candidate stays.
bool better(const Candidate& a, const Candidate& b) { return a.sigma < b.sigma; }

Candidate from_power(const PowerLawFit& fit, bool weighted) {
  return {"power", weighted, fit.f0, fit.sigma, fit.fhat};
}

Candidate from_fixed(const std::string& name, const FixedOrderFit& fit, bool weighted) {
  return {name, weighted, fit.f0, fit.sigma, fit.fhat};
}

// The variant (unweighted, weighted) with the smaller σ; weighted on a tie.
template <typename Fit>
const Fit& pick(const Fit& unweighted, const Fit& weighted, bool& is_weighted) {
  is_weighted = !(unweighted.sigma < weighted.sigma);
  return is_weighted ? weighted : unweighted;
}

FitSummary summarize(const FixedOrderFit& fit, bool weighted) {
  FitSummary sum;
  sum.f0 = fit.f0;
  sum.sigma = fit.sigma;
  sum.weighted = weighted;
  for (std::size_t k = 0; k < fit.exponents.size(); ++k)
    (fit.exponents[k] == 1.0 ? sum.c1 : sum.c2) = fit.coefficients[k];
  return sum;
}

}  // namespace

double eh14_uncertainty(double eps, double sigma, double dev, double range, double fs) {
  if (sigma < range) return fs * eps + sigma + dev;       // eq. 20
  return 3.0 * sigma / range * (eps + sigma + dev);       // eq. 21
}

void eh14_extrapolate(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out) {
  const auto wu = fit_weights(s.h, Weighting::kUniform);
  const auto ww = fit_weights(s.h, Weighting::kInverseH);

  // Every fit in both weightings.
  const PowerLawFit pu = fit_power_law(s, wu, opts.search), pw = fit_power_law(s, ww, opts.search);
  const FixedOrderFit f1u = fit_fixed_orders(s, wu, {1.0}), f1w = fit_fixed_orders(s, ww, {1.0});
  const FixedOrderFit f2u = fit_fixed_orders(s, wu, {2.0}), f2w = fit_fixed_orders(s, ww, {2.0});
  const FixedOrderFit f12u = fit_mixed(s, wu), f12w = fit_mixed(s, ww);

  // 1. Observed order from the power law with the smaller σ.
  bool power_weighted = false;
  const PowerLawFit& power = pick(pu, pw, power_weighted);
  out.power = FitSummary{};
  out.power->f0 = power.f0;
  out.power->p = power.p;
  out.power->c = power.c;
  out.power->sigma = power.sigma;
  out.power->p_found = power.p_found;
  out.power->weighted = power_weighted;
  bool w1 = false, w2 = false, w12 = false;
  out.first = summarize(pick(f1u, f1w, w1), w1);
  out.second = summarize(pick(f2u, f2w, w2), w2);
  out.mixed = summarize(pick(f12u, f12w, w12), w12);

  // 2. Error estimator by observed order.
  Eh14Branch branch;
  std::vector<Candidate> candidates;
  const bool found = power.p_found;
  if (found) branch.p = power.p;
  if (found && power.p >= opts.p_low && power.p < kTheoreticalOrder) {
    branch.order = "expected_order";
    candidates = {from_power(power, power_weighted)};
  } else {
    branch.order = !found ? "no_order" : power.p >= kTheoreticalOrder ? "high_order" : "low_order";
    candidates = {from_fixed("first", f1u, false), from_fixed("first", f1w, true),
                  from_fixed("second", f2u, false), from_fixed("second", f2w, true)};
    if (branch.order != "high_order") {
      candidates.push_back(from_fixed("mixed", f12u, false));
      candidates.push_back(from_fixed("mixed", f12w, true));
    }
  }
  const Candidate* chosen = &candidates.front();
  for (const auto& c : candidates)
    if (better(c, *chosen)) chosen = &c;
  branch.error_estimate = chosen->name + (chosen->weighted ? "_weighted" : "_unweighted");

  // 3-4. Data range and safety factor.
  const double range = data_range(s.f);
  const double sigma = chosen->sigma;
  const bool good_fit = sigma < range;
  branch.scatter = good_fit ? "sigma_below_data_range" : "sigma_at_least_data_range";
  const bool accepted_p = found && power.p >= opts.p_low && power.p < opts.p_high;
  const double fs = good_fit ? (accepted_p ? 1.25 : 3.0) : 3.0 * sigma / range;

  out.method = "eh14_" + branch.error_estimate;
  out.f0 = chosen->f0;
  if (found) out.p = power.p;
  out.sigma_re = sigma;
  out.fs = fs;
  out.sigma_over_range = sigma / range;

  // 5. Uncertainty of every grid.
  for (std::size_t i = 0; i < s.size(); ++i) {
    auto& g = out.grids[i];
    const double fhat = chosen->fhat[i];
    const double eps = std::fabs(fhat - chosen->f0);
    g.fhat = fhat;
    g.u = eh14_uncertainty(eps, sigma, std::fabs(s.f[i] - fhat), range, good_fit ? fs : 3.0);
    if (chosen->f0 != 0) g.rde = *g.u / std::fabs(chosen->f0);
  }
  out.eh14 = branch;
  if (chosen->f0 == 0) out.notes.push_back("f0 = 0: relative discretization errors are undefined");
}

}  // namespace gridfree
