// SPDX-License-Identifier: GPL-3.0-or-later
// The fit window of adaptive series (sched/adaptive_window.h) on hand-made
// series through the library's own extrapolation: coarse grids that follow a
// different law than the fine ones spoil the fit on all grids, the window of
// the finest five is `converged` and recovers f0, and the adaptive decision
// stops with the window where it did not without it; a series converged on
// all its grids keeps them all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report/extrapolator.h"
#include "sched/adaptive_decision.h"
#include "sched/adaptive_series.h"
#include "sched/adaptive_window.h"

namespace gridfree {
namespace {

// Ladder 3.3/1.25^k, k = 0 … 8 (3.3 → 0.554), as the adaptive study runs it.
std::vector<double> ladder_h() {
  std::vector<double> h;
  for (int k = 0; k <= 8; ++k) h.push_back(3.3 / std::pow(1.25, k));
  return h;
}

// f0 = 1000, first order on the fine grids (h ≤ 1.5: the five finest rungs);
// the coarse rungs carry a large fourth-order term on top (+3 h^4: +356 at
// h = 3.3), i.e. they lie outside the asymptotic range of the fine ones.
double spoiled(double h) { return 1000 + 5 * h + (h > 1.5 ? 3 * std::pow(h, 4) : 0.0); }

AdaptiveGrids fine_ladder_settings() {
  AdaptiveGrids a;
  a.target_rde = 0.01;
  a.coarsest_delta_star = 3.3;
  a.ratio = 1.25;
  a.finest_delta_star = 0.3;
  return a;
}

std::vector<AdaptiveRung> rungs() {
  std::vector<AdaptiveRung> out;
  for (double d : adaptive_ladder(fine_ladder_settings())) out.push_back({d, {10, 10, 10}, 100.0, 1e6, ""});
  return out;
}

TEST(AdaptiveWindow, CoarseGridsOfAnotherOrderAreLeftOutAndTheSeriesStops) {
  const auto h = ladder_h();
  std::vector<double> f;
  for (double x : h) f.push_back(spoiled(x));
  const auto extrapolate = library_extrapolator({});
  // Without the window: the fit on all nine grids is not converged.
  const auto full = adaptive_fit_of(extrapolate(h, f), 9);
  ASSERT_NE(full.verdict, "converged");
  const auto without = decide_adaptive_step(fine_ladder_settings(), rungs(), 9, full, 1.0, 1e15);
  EXPECT_EQ(without.kind, AdaptiveDecision::Kind::kContinue) << without.message;

  const WindowedFit w = windowed_extrapolation(h, f, extrapolate);
  EXPECT_EQ(w.used, 5u);  // exactly the five grids with h ≤ 1.5
  EXPECT_EQ(w.left_out, 4u);
  EXPECT_DOUBLE_EQ(w.finest_h, h[8]);
  EXPECT_DOUBLE_EQ(w.coarsest_used_h, h[4]);
  EXPECT_EQ(w.full_set_verdict, full.verdict);
  AdaptiveFit fit = adaptive_fit_of(w.extrapolation, 9);
  fit.window = window_sentence(w);
  EXPECT_EQ(fit.verdict, "converged");
  ASSERT_TRUE(fit.f0 && fit.finest_u);
  // The window is exactly f0 + 5h: the extrapolation returns f0 = 1000 to
  // least-squares round-off (1e-6 relative to values of ~1000).
  EXPECT_NEAR(*fit.f0, 1000, 1e-3);
  const auto with = decide_adaptive_step(fine_ladder_settings(), rungs(), 9, fit, 1.0, 1e15);
  EXPECT_EQ(with.kind, AdaptiveDecision::Kind::kTargetMet) << with.message;
  EXPECT_NE(with.message.find("fit on the 5 finest grids, Δ* 1.35 → 0.554; the 4 coarser ones were left out"),
            std::string::npos)
      << with.message;
}

TEST(AdaptiveWindow, SeriesConvergedOnAllGridsUsesAllOfThem) {
  const auto h = ladder_h();
  std::vector<double> f;
  for (double x : h) f.push_back(1000 + 5 * x + 0.2 * x * x);  // smooth, asymptotic everywhere
  const auto extrapolate = library_extrapolator({});
  const WindowedFit w = windowed_extrapolation(h, f, extrapolate);
  ASSERT_EQ(w.full_set_verdict, "converged");
  EXPECT_EQ(w.used, 9u);
  EXPECT_EQ(w.left_out, 0u);
  EXPECT_EQ(window_sentence(w), "");
  EXPECT_EQ(w.extrapolation, extrapolate(h, f));
}

TEST(AdaptiveWindow, NeverFewerThanFiveGrids) {
  // Four fine grids only below the change of law: no window of ≥ 5 grids is
  // free of the coarse law, none is converged, and the full-set fit stands.
  const auto h = ladder_h();
  std::vector<double> hh(h.begin(), h.end() - 1), f;  // 3.3 … 0.692
  for (double x : hh) f.push_back(spoiled(x));
  const auto extrapolate = library_extrapolator({});
  const WindowedFit w = windowed_extrapolation(hh, f, extrapolate);
  EXPECT_EQ(w.used, hh.size());
  EXPECT_EQ(w.left_out, 0u);
  EXPECT_EQ(w.extrapolation, extrapolate(hh, f));
}

TEST(AdaptiveWindow, OrderOfTheInputDoesNotMatterAndTheExtrapolatorSeamUsesTheWindow) {
  auto h = ladder_h();
  std::vector<double> f;
  for (double x : h) f.push_back(spoiled(x));
  const auto extrapolate = library_extrapolator({});
  const auto forward = windowed_extrapolation(h, f, extrapolate);
  std::reverse(h.begin(), h.end());
  std::reverse(f.begin(), f.end());
  const auto backward = windowed_extrapolation(h, f, extrapolate);
  EXPECT_EQ(backward.used, forward.used);
  EXPECT_EQ(windowed_extrapolator(extrapolate)(h, f), backward.extrapolation);
  EXPECT_EQ(backward.extrapolation["grids"].size(), forward.used);
}

TEST(AdaptiveWindow, RefusesMismatchedInput) {
  EXPECT_THROW(windowed_extrapolation({1.0, 2.0}, {1.0}, library_extrapolator({})), std::invalid_argument);
}

}  // namespace
}  // namespace gridfree
