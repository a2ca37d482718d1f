// SPDX-License-Identifier: GPL-3.0-or-later
// Top-level extrapolation of one series (see extrapolation.h).
#include "extrap/extrapolation.h"

#include <cmath>
#include <string>

#include "core/input_error.h"
#include "extrap/bias_checks.h"
#include "extrap/coverage_record.h"
#include "extrap/eh14.h"
#include "extrap/fm_uncertainty.h"
#include "extrap/gci.h"
#include "extrap/model_average.h"
#include "extrap/verdict.h"

namespace gridfree {
namespace {

// Fewer grids leave no degree of freedom for σ (n − 3 = 0).
constexpr std::size_t kMinGrids = 4;

// Constant data: every fit is the constant itself and the error estimate is 0.
void constant_result(const Series& s, ExtrapolationResult& out) {
  const double f0 = s.f.front();
  out.method = "constant";
  out.f0 = f0;
  out.sigma_re = 0.0;
  out.fs = kMinSafetyFactor;
  out.u0 = 0.0;
  out.power = FitSummary{};
  out.power->f0 = f0;
  out.power->c = 0.0;
  out.power->sigma = 0.0;
  out.power->p_found = false;
  out.mixed = FitSummary{};
  out.mixed->f0 = f0;
  out.mixed->c1 = 0.0;
  out.mixed->c2 = 0.0;
  out.mixed->sigma = 0.0;
  for (auto& g : out.grids) {
    g.fhat = g.f;
    g.u = 0.0;
    g.rde = 0.0;
  }
  out.notes.push_back("f does not change with h: no discretization error is visible, U = 0");
}

}  // namespace

void validate_options(const ExtrapolationOptions& opts) {
  ProblemList problems;
  if (!std::isfinite(opts.p_low) || !std::isfinite(opts.p_high) || !(opts.p_low < opts.p_high))
    problems.add("--p-range", "needs two finite numbers lo < hi, got " + std::to_string(opts.p_low) +
                                  " " + std::to_string(opts.p_high));
  if (!(opts.search.p_min > 0 && opts.search.p_min < opts.search.p_max) ||
      !std::isfinite(opts.search.p_max))
    problems.add("p search range", "needs 0 < p_min < p_max");
  if (opts.search.points_per_side < 3) problems.add("p search points", "needs at least 3 points");
  if (opts.expected_order && !(std::isfinite(*opts.expected_order) && *opts.expected_order > 0))
    problems.add("--order", "the declared order must be a finite number > 0, got " +
                                std::to_string(*opts.expected_order));
  problems.throw_if_any();
}

ExtrapolationMethod parse_method(const std::string& name, const std::string& where) {
  if (name == "averaged") return ExtrapolationMethod::kAveraged;
  if (name == "capped") return ExtrapolationMethod::kCapped;
  if (name == "fm") return ExtrapolationMethod::kFm;
  if (name == "eh14") return ExtrapolationMethod::kEh14;
  throw InputError(where, "unknown extrapolation method \"" + name + "\"; valid: averaged, capped, fm, eh14");
}

ExtrapolationResult extrapolate(const std::vector<double>& h, const std::vector<double>& f,
                                const ExtrapolationOptions& opts) {
  validate_options(opts);
  return extrapolate(make_series(h, f), opts);
}

namespace {

void fit_series(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out) {
  for (std::size_t i = 0; i < s.size(); ++i) out.grids.push_back({s.h[i], s.f[i], {}, {}, {}});
  out.gci = gci_triplets(s);
  if (s.size() >= 2) out.data_range = data_range(s.f);

  if (s.size() < kMinGrids) {
    out.status = "insufficient_grids";
    out.power = FitSummary{};
    out.mixed = FitSummary{};
    out.notes.push_back("fewer than 4 grids: no least-squares fit and no uncertainty estimate "
                        "(the three-grid GCI is still reported)");
    return;
  }
  if (is_constant(s.f)) {
    constant_result(s, out);
    return;
  }
  if (opts.method == ExtrapolationMethod::kEh14)
    eh14_extrapolate(s, opts, out);
  else if (opts.method == ExtrapolationMethod::kAveraged)
    averaged_extrapolate(s, opts, out);
  else
    fm_extrapolate(s, opts, out);
  if (out.f0 && out.sigma_re) out.u0 = extrapolated_value_uncertainty(*out.f0, s.f.front(), *out.sigma_re);
  if (out.u0 && out.model_spread) widen_u0_to_hold(out.model_spread->f0, out);
}

}  // namespace

ExtrapolationResult extrapolate(const Series& s, const ExtrapolationOptions& opts) {
  ExtrapolationResult out;
  fit_series(s, opts, out);
  // The leave-one-out fits use the same method and settings, without checks of their own.
  const SubSeriesF0 refit = [&opts](const Series& sub) {
    ExtrapolationResult r;
    fit_series(sub, opts, r);
    return r.f0;
  };
  const std::vector<std::string> failed = apply_bias_checks(s, opts, refit, out);
  out.verdict = judge(out, opts);
  demote_for_bias(failed, s.h, out.verdict, opts.h_symbol);
  if (opts.method == ExtrapolationMethod::kAveraged && opts.unreliable_range_floor &&
      out.verdict.value == "unreliable")
    floor_unreliable_to_data_range(s, out);
  const std::string record = measured_coverage_sentence(opts.method, opts.expected_order.has_value(),
                                                        out.verdict.value);
  if (!record.empty() && out.method && *out.method != "constant") out.notes.push_back(record);
  return out;
}

}  // namespace gridfree
