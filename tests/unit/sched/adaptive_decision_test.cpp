// SPDX-License-Identifier: GPL-3.0-or-later
// The adaptive stopping rule (sched/adaptive_decision.h) on hand-made
// series: converged and meeting the target stops; pre-asymptotic, too few
// grids, or an RDE above the target continues with the next rung; a cap or
// the end of the ladder ends the series target_not_reached; "saved" is the
// cost of the rungs not run. Then adaptive_fit_of on the library's own
// extrapolation of a manufactured series f = f0 + c·h (p = 1, exact).
#include <gtest/gtest.h>

#include <cmath>

#include "report/extrapolator.h"
#include "sched/adaptive_decision.h"
#include "sched/adaptive_series.h"

namespace gridfree {
namespace {

AdaptiveGrids settings() {
  AdaptiveGrids a;
  a.target_rde = 0.01;
  a.coarsest_delta_star = 3.3;
  a.ratio = 1.25;
  a.finest_delta_star = 0.6;
  return a;
}

// Rungs with round costs: rung k costs 100·2^k CPU s and 1 GiB·2^k.
std::vector<AdaptiveRung> ladder() {
  std::vector<AdaptiveRung> out;
  const auto ds = adaptive_ladder(settings());
  for (std::size_t k = 0; k < ds.size(); ++k)
    out.push_back({ds[k], {10, 10, 10}, 100.0 * std::pow(2.0, k), 1073741824.0 * std::pow(2.0, k), ""});
  return out;
}

AdaptiveFit fit(int ng, const std::string& verdict, double rde) {
  AdaptiveFit f;
  f.ng = ng;
  f.verdict = verdict;
  f.finest_delta_star = 1.35;
  f.finest_rde = rde;
  f.f0 = 1012.4;
  return f;
}

constexpr double kBigMachine = 1e15;

TEST(AdaptiveDecision, LadderIsGeometricDownToFinest) {
  const auto ds = adaptive_ladder(settings());
  // 3.3/1.25^7 = 0.692 ≥ 0.6 > 3.3/1.25^8 = 0.554
  ASSERT_EQ(ds.size(), 8u);
  EXPECT_DOUBLE_EQ(ds.front(), 3.3);
  for (std::size_t k = 1; k < ds.size(); ++k) EXPECT_NEAR(ds[k - 1] / ds[k], 1.25, 1e-12);
  EXPECT_GE(ds.back(), 0.6);
}

TEST(AdaptiveDecision, ConvergedAndMeetingTargetStopsAndCountsTheSaving) {
  const auto l = ladder();
  const auto d = decide_adaptive_step(settings(), l, 5, fit(5, "converged", 0.008), 2.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetMet);
  // rungs 5, 6, 7 not run: 2·(3200 + 6400 + 12800) CPU s
  EXPECT_DOUBLE_EQ(d.saved_cpu_s, 2.0 * (3200 + 6400 + 12800));
  EXPECT_EQ(d.rungs_not_run, 3u);
  EXPECT_NE(d.message.find("RDE 0.8 % ≤ 1 %"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("12.4 core-hours"), std::string::npos) << d.message;  // 44800 s
  EXPECT_EQ(adaptive_status_word(d.kind), "target_met");
}

TEST(AdaptiveDecision, RdeExactlyAtTargetStops) {
  const auto d = decide_adaptive_step(settings(), ladder(), 4, fit(4, "converged", 0.01), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetMet);
}

TEST(AdaptiveDecision, PreAsymptoticContinuesWithTheNextRung) {
  const auto d = decide_adaptive_step(settings(), ladder(), 4, fit(4, "pre-asymptotic", 0.001), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kContinue);
  EXPECT_EQ(d.next_rung, 4u);
  EXPECT_NE(d.message.find("pre-asymptotic"), std::string::npos) << d.message;
  EXPECT_EQ(adaptive_status_word(d.kind), "refining");
}

TEST(AdaptiveDecision, RdeAboveTargetContinues) {
  const auto d = decide_adaptive_step(settings(), ladder(), 6, fit(6, "converged", 0.0101), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kContinue);
  EXPECT_EQ(d.next_rung, 6u);
}

TEST(AdaptiveDecision, FewerThanFourConvergedGridsContinueEvenWithSmallRde) {
  // Four rungs run but one failed: 3 converged grids are no extrapolation.
  const auto d = decide_adaptive_step(settings(), ladder(), 4, fit(3, "converged", 0.001), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kContinue);
  EXPECT_EQ(d.next_rung, 4u);
}

TEST(AdaptiveDecision, MemoryCapEndsTheSeriesTargetNotReached) {
  auto a = settings();
  a.max_memory_bytes = 20.0 * 1073741824.0;  // rung 4 needs 16 GiB, rung 5 needs 32 GiB
  EXPECT_EQ(decide_adaptive_step(a, ladder(), 4, fit(4, "pre-asymptotic", 0.02), 1.0, kBigMachine).kind,
            AdaptiveDecision::Kind::kContinue);
  const auto d = decide_adaptive_step(a, ladder(), 5, fit(5, "pre-asymptotic", 0.02), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetNotReached);
  EXPECT_NE(d.message.find("max_memory"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("best: Δ* 1.35, RDE 2 %"), std::string::npos) << d.message;
  EXPECT_EQ(adaptive_status_word(d.kind), "target_not_reached");
}

TEST(AdaptiveDecision, MachineMemoryIsTheDefaultCap) {
  const auto d = decide_adaptive_step(settings(), ladder(), 5, fit(5, "converged", 0.02), 1.0, 20.0 * 1073741824.0);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetNotReached);
  EXPECT_NE(d.message.find("this machine's memory"), std::string::npos) << d.message;
}

TEST(AdaptiveDecision, CpuCapUsesTheMeasuredScale) {
  auto a = settings();
  a.max_cpu_s = 2000;  // rung 4: model 1600 s
  EXPECT_EQ(decide_adaptive_step(a, ladder(), 4, fit(4, "converged", 0.02), 1.0, kBigMachine).kind,
            AdaptiveDecision::Kind::kContinue);
  // measured times twice the model: 3200 s > 2000 s
  const auto d = decide_adaptive_step(a, ladder(), 4, fit(4, "converged", 0.02), 2.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetNotReached);
  EXPECT_NE(d.message.find("max_cpu_s"), std::string::npos) << d.message;
}

TEST(AdaptiveDecision, EndOfTheLadderEndsTheSeriesTargetNotReached) {
  const auto l = ladder();
  const auto d = decide_adaptive_step(settings(), l, l.size(), fit(8, "converged", 0.02), 1.0, kBigMachine);
  EXPECT_EQ(d.kind, AdaptiveDecision::Kind::kTargetNotReached);
  EXPECT_EQ(d.rungs_not_run, 0u);
  EXPECT_NE(d.message.find("finest_delta_star"), std::string::npos) << d.message;
}

TEST(AdaptiveDecision, FitSummaryReadsTheFinestGridOfTheLibraryExtrapolation) {
  // f = 1000 + 5 h on four rungs: exactly first order; the library finds
  // f0 = 1000 (to its least-squares round-off) and the finest grid is the
  // last rung whatever order the JSON lists the grids in.
  std::vector<double> h = {3.3, 2.64, 2.112, 1.6896}, f;
  for (double x : h) f.push_back(1000 + 5 * x);
  const auto ex = library_extrapolator({})(h, f);
  const auto fit = adaptive_fit_of(ex, 4);
  ASSERT_TRUE(fit.finest_delta_star && fit.finest_rde && fit.f0);
  EXPECT_DOUBLE_EQ(*fit.finest_delta_star, 1.6896);
  EXPECT_NEAR(*fit.f0, 1000, 1e-6);
  EXPECT_FALSE(fit.verdict.empty());
  EXPECT_GE(*fit.finest_rde, 0);
}

TEST(AdaptiveDecision, FitSummaryOfNoExtrapolationIsEmpty) {
  const auto fit = adaptive_fit_of(nlohmann::json(), 1);
  EXPECT_EQ(fit.ng, 1);
  EXPECT_FALSE(fit.finest_rde.has_value());
  EXPECT_TRUE(fit.verdict.empty());
}

}  // namespace
}  // namespace gridfree
