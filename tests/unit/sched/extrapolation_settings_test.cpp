// SPDX-License-Identifier: GPL-3.0-or-later
// A study's "extrapolation" settings reach the extrapolation of its series:
// weights, p_range, method and expected_order are read from the stored
// definition, the weights change the fit, and a declared order judges it (uniform vs 1/h weights give different f0 on data
// that no single curve of the family fits exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "report/extrapolator.h"
#include "sched/series_finish.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

TEST(ExtrapolationSettings, ReadFromTheStoredStudy) {
  const auto dir = test_support::scratch_root("extrapolation_settings_test");
  fs::create_directories(dir);
  const auto db = dir / "settings.sqlite";
  fs::remove(db);
  Store store(db);
  Study s;
  s.name = "a";
  s.definition = {{"name", "a"},
                  {"extrapolation",
                   {{"weights", "uniform"}, {"p_range", {0.6, 1.9}}, {"method", "eh14"}, {"expected_order", 2}}}};
  const auto id = store.submit(s, ExpandedStudy{}).study_id;
  const ExtrapolatorSettings got = study_extrapolation_settings(store, id);
  EXPECT_EQ(got.weights, "uniform");
  EXPECT_EQ(got.method, "eh14");
  EXPECT_DOUBLE_EQ(got.p_low, 0.6);
  EXPECT_DOUBLE_EQ(got.p_high, 1.9);
  ASSERT_TRUE(got.expected_order.has_value());
  EXPECT_DOUBLE_EQ(*got.expected_order, 2.0);

  Study d;
  d.name = "defaults";
  d.definition = {{"name", "defaults"}};
  const ExtrapolatorSettings def = study_extrapolation_settings(store, store.submit(d, ExpandedStudy{}).study_id);
  EXPECT_EQ(def.weights, "inverse_h");
  EXPECT_EQ(def.method, "averaged");
  EXPECT_FALSE(def.expected_order.has_value());
}

TEST(ExtrapolationSettings, ADeclaredOrderTheDataContradictIsNotConverged) {
  // f = 1 + h on 7 grids: exact first order, converged unless second order is declared.
  std::vector<double> h, f;
  for (int k = 0; k < 7; ++k) h.push_back(0.01 * std::pow(2.0, k)), f.push_back(1 + h.back());
  ExtrapolatorSettings plain, declared;
  declared.expected_order = 2.0;
  EXPECT_EQ(library_extrapolator(plain)(h, f)["verdict"]["value"], "converged");
  const auto j = library_extrapolator(declared)(h, f);
  EXPECT_EQ(j["verdict"]["value"], "pre-asymptotic");
  EXPECT_EQ(j["bias_checks"]["order_consistent"], false);
}

TEST(ExtrapolationSettings, WeightsChangeTheFit) {
  // f = 1000 + 5 h + noise of ±1: no power law fits it exactly, so how the
  // residuals are weighted moves f0.
  const std::vector<double> h = {0.5, 0.75, 1.0, 1.5, 2.0, 3.0};
  const std::vector<double> f = {1003.5, 1002.8, 1006.0, 1006.5, 1011.0, 1014.0};
  ExtrapolatorSettings inverse_h, uniform;
  uniform.weights = "uniform";
  const auto a = library_extrapolator(inverse_h)(h, f);
  const auto b = library_extrapolator(uniform)(h, f);
  ASSERT_TRUE(a["f0"].is_number());
  ASSERT_TRUE(b["f0"].is_number());
  EXPECT_GT(std::abs(a["f0"].get<double>() - b["f0"].get<double>()), 1e-6);
}

}  // namespace
}  // namespace gridfree
