// SPDX-License-Identifier: GPL-3.0-or-later
// Filter integration names (deposition/filter_integration.h): every value
// has one name and the name parses back to it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "deposition/filter_integration.h"

namespace gridfree {
namespace {

TEST(FilterIntegrationNames, RoundTripAndAreDistinct) {
  std::set<std::string> seen;
  for (const auto& n : filter_integration_names()) {
    EXPECT_EQ(filter_integration_name(n.value), n.name);
    EXPECT_EQ(parse_filter_integration(n.name), n.value);
    EXPECT_TRUE(seen.insert(std::string(n.name)).second) << n.name;
  }
  EXPECT_EQ(seen, (std::set<std::string>{"steps", "exact", "gaussian"}));
  EXPECT_FALSE(parse_filter_integration("Gaussian").has_value());
  EXPECT_FALSE(parse_filter_integration("").has_value());
}

}  // namespace
}  // namespace gridfree
