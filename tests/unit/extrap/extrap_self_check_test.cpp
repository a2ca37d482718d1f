// SPDX-License-Identifier: GPL-3.0-or-later
// Coverage self-check (extrap/self_check.h): which windows are made, how
// each is judged against the whole series' f0, the summary and its
// warning rule; then the library's own extrapolation on exact data.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/extrapolation.h"
#include "extrap/self_check.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

// A stand-in extrapolation: f0 = 10 for the whole series, and for a window
// f1 = its finest f with U₁ = u1_of(h_fine) and f0 ± U₀ = f1 ± U₁.
struct FakeExtrapolator {
  std::size_t whole = 0;
  std::function<double(double)> u1_of;
  WindowFit operator()(const std::vector<double>& h, const std::vector<double>& f) const {
    if (h.size() == whole) return {"converged", 10.0, 0.1, f.front(), 0.1, {}, {}};
    return {"pre-asymptotic", f.front(), u1_of(h.front()), f.front(), u1_of(h.front()), {}, {}};
  }
};

TEST(SelfCheck, WindowsAreEveryRunOfFourOrMoreCoarserGrids) {
  const std::vector<double> h = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> f(8, 9.5);  // every window's f1 is 0.5 from the reference 10
  const CoverageCheck c = coverage_self_check(h, f, FakeExtrapolator{8, [](double) { return 1.0; }});
  ASSERT_EQ(c.status, "checked");
  // Among the 7 coarser grids: 4 windows of 4, 3 of 5, 2 of 6, 1 of 7.
  ASSERT_EQ(c.windows.size(), 10u);
  for (const auto& w : c.windows) {
    EXPECT_GE(w.first, 1u);  // the finest grid is never in a window
    EXPECT_GE(w.count, 4u);
    EXPECT_LE(w.first + w.count, 8u);
    EXPECT_EQ(w.h_fine, h[w.first]);
    EXPECT_EQ(w.h_coarse, h[w.first + w.count - 1]);
  }
  EXPECT_EQ(c.judged, 10);
  EXPECT_EQ(c.covered, 10);
  EXPECT_FALSE(c.below_promise());
  EXPECT_EQ(*c.reference, 10.0);
  EXPECT_EQ(c.reference_verdict, "converged");
}

TEST(SelfCheck, WindowsHaveAtMostEightGrids) {
  std::vector<double> h;
  for (int i = 1; i <= 12; ++i) h.push_back(i);
  const CoverageCheck c =
      coverage_self_check(h, std::vector<double>(12, 9.5), FakeExtrapolator{12, [](double) { return 1.0; }});
  // Among the 11 coarser grids: 8 windows of 4, 7 of 5, 6 of 6, 5 of 7, 4 of 8.
  EXPECT_EQ(c.windows.size(), 30u);
  for (const auto& w : c.windows) EXPECT_LE(w.count, 8u);
}

TEST(SelfCheck, AWindowIsCoveredWhenTheAnswerIsWithinItsU1) {
  const std::vector<double> h = {1, 2, 3, 4, 5, 6};
  const std::vector<double> f(6, 9.5);
  // U₁ = 0.6 for windows starting at Δ* 2 (covered: 0.5 ≤ 0.6), 0.4 from Δ* 3 (missed).
  const CoverageCheck c = coverage_self_check(h, f, FakeExtrapolator{6, [](double hf) { return hf < 2.5 ? 0.6 : 0.4; }});
  ASSERT_EQ(c.windows.size(), 3u);  // 2 windows of 4 grids, 1 of 5
  EXPECT_EQ(c.judged, 3);
  EXPECT_EQ(c.covered, 2);
  for (const auto& w : c.windows) {
    ASSERT_TRUE(w.distance.has_value());
    EXPECT_DOUBLE_EQ(*w.distance, 0.5 / w.fit.u1.value());
    EXPECT_EQ(*w.covered, w.h_fine < 2.5);
  }
  EXPECT_TRUE(c.below_promise());  // 2 of 3 < 95 %
  EXPECT_NE(c.summary().find("2 of 3"), std::string::npos) << c.summary();
  EXPECT_NE(c.summary().find("below the 95 %"), std::string::npos) << c.summary();
}

TEST(SelfCheck, TooFewGridsOrNoReference) {
  const FakeExtrapolator fake{5, [](double) { return 1.0; }};
  EXPECT_EQ(coverage_self_check({1, 2, 3, 4, 5}, {1, 2, 3, 4, 5}, fake).status, "too_few_grids");
  const auto no_f0 = [](const std::vector<double>&, const std::vector<double>&) { return WindowFit{"unreliable", {}, {}, {}, {}, {}, {}}; };
  const CoverageCheck c = coverage_self_check({1, 2, 3, 4, 5, 6}, {1, 2, 3, 4, 5, 6}, no_f0);
  EXPECT_EQ(c.status, "no_reference");
  EXPECT_TRUE(c.windows.empty());
  EXPECT_FALSE(c.below_promise());
}

TEST(SelfCheck, WindowsWithoutAnUncertaintyAreNotJudged) {
  const auto fit = [](const std::vector<double>& h, const std::vector<double>& f) {
    if (h.size() == 6) return WindowFit{"converged", 10.0, 0.1, f.front(), 0.1, {}, {}};
    return WindowFit{"insufficient_grids", {}, {}, f.front(), {}, {}, {}};
  };
  const CoverageCheck c = coverage_self_check({1, 2, 3, 4, 5, 6}, std::vector<double>(6, 9.0), fit);
  EXPECT_EQ(c.windows.size(), 3u);
  EXPECT_EQ(c.judged, 0);
  EXPECT_FALSE(c.below_promise());
  EXPECT_NE(c.summary().find("no coarser window"), std::string::npos);
}

TEST(SelfCheck, TheLibraryCoversAnExactPowerLaw) {
  // f = 5 + 0.3 h^1.5 on 9 grids: every window's U₁ must cover f0 = 5 of the
  // whole series, which the power law recovers exactly.
  const auto h = test::geometric_h(9, 0.2, 3.3);
  const auto f = test::power_law(h, 5.0, 0.3, 1.5);
  const ExtrapolationOptions opts;
  const CoverageCheck c = coverage_self_check(
      h, f, [&opts](const auto& wh, const auto& wf) { return window_fit(extrapolate(Series{wh, wf}, opts)); });
  ASSERT_EQ(c.status, "checked");
  EXPECT_NEAR(*c.reference, 5.0, 1e-9);
  EXPECT_EQ(c.judged, static_cast<int>(c.windows.size()));
  EXPECT_EQ(c.covered, c.judged);
  EXPECT_EQ(c.f0_covered, c.judged);
  const auto j = to_ordered_json(c);
  EXPECT_EQ(j["windows"].size(), c.windows.size());
  EXPECT_EQ(j["status"], "checked");
  EXPECT_EQ(j["below_promise"], false);
  // Stored as JSON and read back (the database's series.coverage_json): the same check.
  const CoverageCheck back = coverage_from_json(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(to_ordered_json(back).dump(), j.dump());
}

}  // namespace
}  // namespace gridfree
