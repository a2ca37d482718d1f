// SPDX-License-Identifier: GPL-3.0-or-later
// Observed orders of accuracy of the flow solver and the filter on
// manufactured solutions (verify/): the same checks `gridfree-worker verify`
// runs, on the quick grid sequence. Expected: 1 for FOU, 2 for the other
// schemes (L1 norm: limiter clipping at extrema costs O(h) over a region of
// width O(h)), 2 for the filter; pass = within 0.2 of expected or above.
#include <gtest/gtest.h>
#include <omp.h>

#include "verify/filter_order.h"
#include "verify/manufactured_flow.h"
#include "verify/verify.h"

namespace gridfree {
namespace {

const std::vector<int> kGrids{16, 32, 64};

void expect_order(const OrderStudy& s) {
  ASSERT_TRUE(s.failure.empty()) << s.failure;
  for (std::size_t i = 0; i + 1 < s.errors.size(); ++i)
    EXPECT_LT(s.errors[i + 1], s.errors[i]) << s.scheme << ": error must fall with h";
  EXPECT_TRUE(s.passed()) << s.equation << " " << s.scheme << ": observed " << s.observed_order
                          << ", expected " << s.expected_order;
}

TEST(ManufacturedFlow, FirstOrderUpwindIsFirstOrder) { expect_order(manufactured_flow_order(Limiter::kFou, kGrids)); }
TEST(ManufacturedFlow, CentralIsSecondOrder) { expect_order(manufactured_flow_order(Limiter::kCentral, kGrids)); }
TEST(ManufacturedFlow, SuperbeeIsSecondOrder) { expect_order(manufactured_flow_order(Limiter::kSuperbee, kGrids)); }
TEST(ManufacturedFlow, VanLeerIsSecondOrder) { expect_order(manufactured_flow_order(Limiter::kVanLeer, kGrids)); }
TEST(ManufacturedFlow, MusclIsSecondOrder) { expect_order(manufactured_flow_order(Limiter::kMuscl, kGrids)); }
TEST(ManufacturedFlow, MinmodIsSecondOrder) { expect_order(manufactured_flow_order(Limiter::kMinmod, kGrids)); }

TEST(ManufacturedFilter, FilterIsSecondOrder) { expect_order(filter_order({16, 32, 64})); }

// run_code_verification solves the grids concurrently, one per thread: the
// studies must come out the same, bit for bit, with 1 and 2 threads.
TEST(CodeVerification, ResultsDoNotDependOnTheThreadCount) {
  VerifyOptions options;
  options.quick = true;
  options.schemes = {Limiter::kFou};
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = run_code_verification(options);
  omp_set_num_threads(2);
  const auto two = run_code_verification(options);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), 2u);  // the FOU flow study and the filter study
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t s = 0; s < one.size(); ++s) {
    EXPECT_EQ(one[s].equation, two[s].equation);
    EXPECT_EQ(one[s].grids, (std::vector<int>{16, 32, 64}));
    EXPECT_EQ(one[s].errors, two[s].errors);
    EXPECT_EQ(one[s].iterations, two[s].iterations);
  }
}

// --grids: every study runs on the grids given (h = 1/n), not the default set.
TEST(CodeVerification, GridsOptionSetsEveryStudysGrids) {
  VerifyOptions options;
  options.grids = {12, 16, 24};
  options.schemes = {Limiter::kFou};
  const auto studies = run_code_verification(options);
  ASSERT_EQ(studies.size(), 2u);
  for (const auto& s : studies) {
    EXPECT_EQ(s.grids, options.grids) << s.equation;
    ASSERT_EQ(s.h.size(), 3u);
    EXPECT_DOUBLE_EQ(s.h[2], 1.0 / 24);
    EXPECT_TRUE(s.failure.empty()) << s.failure;
  }
}

TEST(ObservedOrder, ExactPowerLawGivesItsExponent) {
  // e = 3 h^1.5 on h = 1/4, 1/8: the formula must return 1.5 exactly.
  EXPECT_NEAR(observed_order({0.25, 0.125}, {3 * std::pow(0.25, 1.5), 3 * std::pow(0.125, 1.5)}), 1.5, 1e-12);
}

}  // namespace
}  // namespace gridfree
