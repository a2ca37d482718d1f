// SPDX-License-Identifier: GPL-3.0-or-later
// Reports of external series (report/external_labels.h): the chart names
// the declared quantity with its description and units and h with its
// declared meaning; a physical series keeps DP* and Δ*.
#include <gtest/gtest.h>

#include "report/chart_series.h"
#include "report/external_labels.h"
#include "report_test_data.h"

namespace gridfree {
namespace {

using nlohmann::json;

TEST(ExternalLabels, QuantityAndHFromTheDefinition) {
  EXPECT_EQ(external_quantity_label("ke", "mean kinetic energy", "m^2/s^2"), "ke: mean kinetic energy [m^2/s^2]");
  EXPECT_EQ(external_quantity_label("ratio", "", "1"), "ratio");
  EXPECT_EQ(external_h_label("1 / N"), "h = 1 / N");
  EXPECT_EQ(external_h_label(json{{"cells", "N * N"}, {"volume", 0.01}, {"dim", 2}}),
            "h = (V / cells)^(1/2), cells = N * N, V = 0.01");
  const json definition = json::parse(R"({"cases": {"cavity": {"external": {"h": "0.1 / N",
      "collect": {"quantities": {"ke": {"units": "m^2/s^2", "description": "mean kinetic energy"}}}}}}})");
  SeriesKey key{"cavity", "", 0, "", ""};
  key.quantity = "ke";
  SeriesData sd;
  sd.case_name = "cavity";
  label_external_series(definition, key, sd);
  EXPECT_EQ(sd.label(), "cavity ke");
  EXPECT_EQ(sd.value_axis(), "ke: mean kinetic energy [m^2/s^2]");
  EXPECT_EQ(sd.h_axis(), "h = 0.1 / N");
}

// A case that inherits its `external` section through "extends" is
// labelled from the inherited section (the stored definition keeps
// "extends"; the study resolves it).
TEST(ExternalLabels, AnInheritedExternalSectionLabelsTheSeries) {
  const json definition = json::parse(R"({"cases": {
      "cavity": {"external": {"h": "0.1 / N",
        "collect": {"quantities": {"ke": {"units": "m^2/s^2", "description": "mean kinetic energy"}}}}},
      "cavity-nu2": {"extends": "cavity", "external": {"version": "v2"}}}})");
  SeriesKey key{"cavity-nu2", "", 0, "", ""};
  key.quantity = "ke";
  SeriesData sd;
  sd.case_name = "cavity-nu2";
  label_external_series(definition, key, sd);
  EXPECT_EQ(sd.value_axis(), "ke: mean kinetic energy [m^2/s^2]");
  EXPECT_EQ(sd.h_axis(), "h = 0.1 / N");
}

TEST(ExternalLabels, SeriesChartNamesTheQuantityNotDpStar) {
  auto s = test::synthetic_summaries();
  const Chart physical = series_chart(s[0], 0);
  EXPECT_EQ(physical.y.label, "DP* = Δp / (ρ_{g} U_{0}^{2})");
  EXPECT_EQ(physical.x.label, "Δ* (cell size / particle diameter)");
  s[0].series.quantity = "ke";
  s[0].series.quantity_label = "ke: mean kinetic energy [m^2/s^2]";
  s[0].series.h_label = "h = 1 / N";
  const Chart external = series_chart(s[0], 0);
  EXPECT_EQ(external.y.label, "ke: mean kinetic energy [m^2/s^2]");
  EXPECT_EQ(external.x.label, "h = 1 / N");
  EXPECT_EQ(external.title.rfind("ke vs h: ", 0), 0u) << external.title;
}

}  // namespace
}  // namespace gridfree
