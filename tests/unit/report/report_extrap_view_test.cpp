// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the adapter from the contract's extrapolation JSON (docs/INTERFACE.md §4)
// to the report's ExtrapolationView.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "report/extrap_view.h"

namespace gridfree {
namespace {

// The example printed by `gridfree extrapolate` in docs/INTERFACE.md §4 (with a
// second grid, out of order, to check sorting).
const char* kContractExample = R"json({
  "status": "ok", "method": "power",
  "f0": 1158.8, "p": 1.03, "sigma_re": 0.12, "data_range": 0.17, "fs": 2.1,
  "fits": {"power": {"f0": 1158.8, "p": 1.03, "c": 0.4, "sigma": 0.12, "p_found": true},
           "mixed": {"f0": 1158.79, "c1": 0.3, "c2": 0.05, "sigma": 0.13}},
  "grids": [{"h": 0.5, "f": 1159.1, "fhat": 1159.0, "u": 0.75, "rde": 0.00065},
            {"h": 0.16, "f": 1158.9, "fhat": 1158.85, "u": 0.3, "rde": 0.0003}],
  "gci": [{"h": [0.16, 0.19, 0.23], "p": 1.2, "f_ext": 1158.7, "gci_fine": 0.001,
           "convergence": "oscillatory", "status": "ok"},
          {"h": [0.19, 0.23, 0.5], "p": null, "f_ext": null, "gci_fine": null,
           "convergence": "divergent", "status": "failed"}]
})json";

TEST(ReportExtrapView, ReadsTheContractExample) {
  const ExtrapolationView v = from_json(nlohmann::json::parse(kContractExample));
  EXPECT_EQ(v.status, "ok");
  EXPECT_EQ(v.method, "power");
  EXPECT_DOUBLE_EQ(*v.f0, 1158.8);
  EXPECT_DOUBLE_EQ(*v.p, 1.03);
  EXPECT_DOUBLE_EQ(*v.fs, 2.1);
  EXPECT_TRUE(v.power.p_found);
  EXPECT_DOUBLE_EQ(*v.power.c, 0.4);
  EXPECT_DOUBLE_EQ(*v.mixed.c2, 0.05);
  ASSERT_EQ(v.grids.size(), 2u);
  EXPECT_DOUBLE_EQ(v.grids[0].h, 0.16);  // sorted finest first
  EXPECT_DOUBLE_EQ(*v.grids[1].u, 0.75);
  ASSERT_EQ(v.gci.size(), 2u);
  EXPECT_DOUBLE_EQ(v.gci[0].h[2], 0.23);
  EXPECT_EQ(v.gci[0].convergence, "oscillatory");
  EXPECT_FALSE(v.gci[1].f_ext.has_value());  // null → empty
  EXPECT_EQ(v.gci[1].status, "failed");
  // σ_RE/R_f = 0.12/0.17.
  EXPECT_DOUBLE_EQ(*v.fit_quality(), 0.12 / 0.17);
  ASSERT_NE(v.grid_at(0.5), nullptr);
  EXPECT_DOUBLE_EQ(v.grid_at(0.5)->f, 1159.1);
  EXPECT_EQ(v.grid_at(0.3), nullptr);
}

TEST(ReportExtrapView, InsufficientGridsHasNullsAndNoUncertainty) {
  const ExtrapolationView v = from_json(nlohmann::json::parse(R"({
    "status": "insufficient_grids", "method": null, "f0": null, "p": null,
    "sigma_re": null, "data_range": 0.0, "fs": null,
    "fits": {"power": {"f0": null, "p": null, "c": null, "sigma": null, "p_found": false},
             "mixed": {"f0": null, "c1": null, "c2": null, "sigma": null}},
    "grids": [{"h": 1, "f": 2, "fhat": null, "u": null, "rde": null}], "gci": []})"));
  EXPECT_EQ(v.status, "insufficient_grids");
  EXPECT_FALSE(v.f0.has_value());
  EXPECT_FALSE(v.fit_quality().has_value());  // R_f = 0 → no ratio
  EXPECT_FALSE(v.power.p_found);
  ASSERT_EQ(v.grids.size(), 1u);
  EXPECT_FALSE(v.grids[0].u.has_value());
}

TEST(ReportExtrapView, MissingKeysAreEmpty) {
  const ExtrapolationView v = from_json(nlohmann::json::parse(R"({"status": "ok"})"));
  EXPECT_FALSE(v.f0.has_value());
  EXPECT_TRUE(v.grids.empty());
  EXPECT_TRUE(v.gci.empty());
}

TEST(ReportExtrapView, WrongTypesNameTheirJsonPointer) {
  try {
    from_json(nlohmann::json::parse(R"({"grids": [{"h": 1, "f": "x"}]})"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].where, "/grids/0/f");
  }
  try {
    from_json(nlohmann::json::parse(R"({"gci": [{"h": [1, 2]}]})"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems()[0].where, "/gci/0/h");
  }
  EXPECT_THROW(from_json(nlohmann::json::array()), InputError);
  EXPECT_THROW(from_json(nlohmann::json::parse(R"({"f0": "1158"})")), InputError);
}

}  // namespace
}  // namespace gridfree
