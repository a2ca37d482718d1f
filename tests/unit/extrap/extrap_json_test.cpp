// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON of docs/INTERFACE.md §4: keys, nulls, ordering of grids and triplets.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/extrapolation.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

void expect_keys(const nlohmann::json& j, const std::vector<std::string>& keys) {
  for (const auto& k : keys) EXPECT_TRUE(j.contains(k)) << "missing key " << k << " in " << j.dump();
}

TEST(ExtrapJson, ContractKeysArePresent) {
  const auto h = test::oscillatory_h();
  const nlohmann::json j = to_json(extrapolate(h, test::oscillatory_f(h)));
  expect_keys(j, {"status", "method", "f0", "p", "sigma_re", "data_range", "fs", "fits", "grids", "gci"});
  expect_keys(j["fits"]["power"], {"f0", "p", "c", "sigma", "p_found"});
  expect_keys(j["fits"]["mixed"], {"f0", "c1", "c2", "sigma"});
  EXPECT_EQ(j["status"], "ok");
  EXPECT_TRUE(j["fits"]["power"]["p_found"].is_boolean());
  ASSERT_EQ(j["grids"].size(), 18u);
  for (const auto& g : j["grids"]) expect_keys(g, {"h", "f", "fhat", "u", "rde"});
  for (std::size_t i = 1; i < j["grids"].size(); ++i)
    EXPECT_LT(j["grids"][i - 1]["h"].get<double>(), j["grids"][i]["h"].get<double>());
  ASSERT_EQ(j["gci"].size(), 16u);
  for (std::size_t i = 0; i < j["gci"].size(); ++i) {
    const auto& t = j["gci"][i];
    expect_keys(t, {"h", "p", "f_ext", "gci_fine", "convergence", "status"});
    ASSERT_EQ(t["h"].size(), 3u);
    EXPECT_EQ(t["h"][0], j["grids"][i]["h"]);  // triplet i starts at grid i: finest first
  }
}

TEST(ExtrapJson, UncomputableNumbersAreNull) {
  const nlohmann::json j = to_json(extrapolate({1, 2, 4}, {1.0, 1.0, 1.5}));
  EXPECT_EQ(j["status"], "insufficient_grids");
  for (const char* k : {"method", "f0", "p", "sigma_re", "fs"}) EXPECT_TRUE(j[k].is_null()) << k;
  EXPECT_DOUBLE_EQ(j["data_range"].get<double>(), 0.25);
  EXPECT_TRUE(j["fits"]["power"]["f0"].is_null());
  EXPECT_TRUE(j["fits"]["mixed"]["c2"].is_null());
  for (const auto& g : j["grids"]) {
    EXPECT_TRUE(g["fhat"].is_null());
    EXPECT_TRUE(g["u"].is_null());
    EXPECT_TRUE(g["rde"].is_null());
  }
  EXPECT_EQ(j["gci"][0]["status"], "zero_difference");
  EXPECT_TRUE(j["gci"][0]["p"].is_null());
  EXPECT_TRUE(j["gci"][0]["gci_fine"].is_null());
}

TEST(ExtrapJson, EqualsTheStructFieldForField) {
  const auto h = test::default_h();
  const auto r = extrapolate(h, test::power_law(h, 2.0, 0.1, 1.0));
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["method"], *r.method);
  EXPECT_EQ(j["f0"].get<double>(), *r.f0);  // full precision survives
  EXPECT_EQ(j["fits"]["power"]["c"].get<double>(), *r.power->c);
  EXPECT_EQ(j["grids"][3]["u"].get<double>(), *r.grids[3].u);
  const auto oj = to_ordered_json(r);
  EXPECT_EQ(oj.begin().key(), "status");  // documented order for people reading it
  EXPECT_EQ(nlohmann::json(oj), j);
}

TEST(ExtrapJson, Eh14AddsItsBranchAndFits) {
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kEh14;
  const auto h = test::default_h();
  const nlohmann::json j = to_json(extrapolate(h, test::power_law(h, 2.0, 0.1, 1.0), opts));
  expect_keys(j, {"eh14"});
  expect_keys(j["eh14"], {"order_branch", "scatter_branch", "error_estimate", "p_observed"});
  expect_keys(j["fits"], {"power", "mixed", "first", "second"});
  EXPECT_TRUE(j["fits"]["power"]["weighted"].is_boolean());
  EXPECT_EQ(j["method"].get<std::string>().rfind("eh14_", 0), 0u);
}

}  // namespace
}  // namespace gridfree
