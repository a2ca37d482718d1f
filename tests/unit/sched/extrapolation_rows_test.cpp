// SPDX-License-Identifier: GPL-3.0-or-later
// The stored rows of a series' extrapolation (sched/series_finish.h): one
// row per reported fit and `chosen` on the fit f0 comes from, whatever the
// method — so v_series' f0 (the chosen row) is never empty for a fitted series.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/extrapolation.h"
#include "sched/series_finish.h"

namespace gridfree {
namespace {

std::vector<SeriesPoint> points_for(const std::vector<double>& h, const std::vector<double>& f) {
  std::vector<SeriesPoint> points;
  for (std::size_t i = 0; i < h.size(); ++i) {
    SeriesPoint p;
    p.job_id = static_cast<long long>(i + 1);
    p.delta_star = h[i];
    p.dp_star = f[i];
    p.result_status = "converged";
    points.push_back(p);
  }
  return points;
}

// The chosen row of the library's result with `method`, and its f0.
void expect_chosen(ExtrapolationMethod method, const std::vector<double>& f, const std::string& row) {
  const std::vector<double> h = {0.5, 0.75, 1.0, 1.5, 2.0, 3.0};
  ExtrapolationOptions opts;
  opts.method = method;
  const nlohmann::json ex = to_json(extrapolate(h, f, opts));
  std::vector<ExtrapolationRow> fits;
  std::vector<UncertaintyRow> unc;
  extrapolation_rows(ex, points_for(h, f), fits, unc);
  int chosen = 0;
  for (const auto& r : fits) {
    if (!r.chosen) continue;
    ++chosen;
    EXPECT_EQ(r.method, row) << ex["method"];
    ASSERT_TRUE(r.f0.has_value());
    EXPECT_DOUBLE_EQ(*r.f0, ex["f0"].get<double>());
  }
  EXPECT_EQ(chosen, 1) << ex["method"];
  EXPECT_EQ(unc.size(), h.size());
}

TEST(ExtrapolationRows, TheChosenRowIsTheFitF0ComesFrom) {
  std::vector<double> cubic, linear;
  for (double h : {0.5, 0.75, 1.0, 1.5, 2.0, 3.0}) {
    cubic.push_back(10 + h * h * h);    // observed order 3: capped / mixed
    linear.push_back(10 + 0.5 * h);     // order 1: the power law
  }
  expect_chosen(ExtrapolationMethod::kCapped, cubic, "capped");
  expect_chosen(ExtrapolationMethod::kFm, cubic, "mixed");
  expect_chosen(ExtrapolationMethod::kCapped, linear, "power");
  expect_chosen(ExtrapolationMethod::kCapped, std::vector<double>(6, 7.0), "constant");
  EXPECT_EQ(chosen_fit_name("eh14_second_weighted"), "second");
  EXPECT_EQ(chosen_fit_name("eh14_power_unweighted"), "power");
}

}  // namespace
}  // namespace gridfree
