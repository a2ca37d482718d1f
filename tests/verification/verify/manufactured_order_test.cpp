// Observed orders of accuracy of the flow solver and the filter on
// manufactured solutions (verify/): the same checks `gridfree-worker verify`
// runs, on the quick grid sequence. Expected: 1 for FOU, 2 for the other
// schemes (L1 norm: limiter clipping at extrema costs O(h) over a region of
// width O(h)), 2 for the filter; pass = within 0.2 of expected or above.
#include <gtest/gtest.h>

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

TEST(ObservedOrder, ExactPowerLawGivesItsExponent) {
  // e = 3 h^1.5 on h = 1/4, 1/8: the formula must return 1.5 exactly.
  EXPECT_NEAR(observed_order({0.25, 0.125}, {3 * std::pow(0.25, 1.5), 3 * std::pow(0.125, 1.5)}), 1.5, 1e-12);
}

}  // namespace
}  // namespace gridfree
