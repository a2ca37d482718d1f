// SPDX-License-Identifier: GPL-3.0-or-later
// The measured coverage every result quotes (extrap/coverage_record.h) is the
// measurement docs/EXTRAPOLATION.md prints: each method's row of the "All
// sources" table (windows; f₁ ± U₁ covers; f0 ± U₀ covers per verdict class)
// equals its record, so that neither can change without the other.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/coverage_record.h"
#include "project_paths.h"
#include "test_files.h"

namespace gridfree {
namespace {

namespace ts = test_support;

// The cells of the table row that starts "| label |" in the section of
// EXTRAPOLATION.md about other codes' series (empty when there is none).
std::vector<std::string> record_row(const std::string& doc, const std::string& label) {
  const std::size_t section = doc.find("## Coverage on other codes' series");
  const std::size_t at = doc.find("\n| " + label + " |", section);
  if (section == std::string::npos || at == std::string::npos) return {};
  const std::string line = doc.substr(at + 1, doc.find('\n', at + 1) - at - 1);
  std::vector<std::string> cells;
  std::size_t from = 1;
  for (std::size_t bar = line.find('|', from); bar != std::string::npos; bar = line.find('|', from)) {
    std::string cell = line.substr(from, bar - from);
    std::erase(cell, '*');  // bold marks
    cells.push_back(cell);
    from = bar + 1;
  }
  return cells;
}

struct Row {
  const char* label;
  ExtrapolationMethod method;
  bool with_order;
};

TEST(CoverageRecord, EqualsTheAllSourcesTableOfExtrapolationMd) {
  const std::string doc = ts::slurp(ts::kSourceDir / "docs/EXTRAPOLATION.md");
  ASSERT_FALSE(doc.empty());
  const std::vector<Row> rows = {{"averaged (default)", ExtrapolationMethod::kAveraged, false},
                                 {"averaged, order declared", ExtrapolationMethod::kAveraged, true},
                                 {"capped", ExtrapolationMethod::kCapped, false},
                                 {"capped, order declared", ExtrapolationMethod::kCapped, true},
                                 {"fm", ExtrapolationMethod::kFm, false},
                                 {"fm, order declared", ExtrapolationMethod::kFm, true},
                                 {"eh14", ExtrapolationMethod::kEh14, false},
                                 {"eh14, order declared", ExtrapolationMethod::kEh14, true}};
  for (const Row& r : rows) {
    const std::vector<std::string> cells = record_row(doc, r.label);
    ASSERT_GE(cells.size(), 4u) << "no row '" << r.label << "' in the all-sources table";
    const MeasuredCoverage m = measured_coverage(r.method, r.with_order);
    ASSERT_EQ(m.classes.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      int windows = 0;
      double u1 = 0, u0 = 0;
      ASSERT_EQ(std::sscanf(cells[k + 1].c_str(), " %d; %lf %%; %lf %%", &windows, &u1, &u0), 3)
          << r.label << ": '" << cells[k + 1] << "'";
      const ClassCoverage& c = m.classes[k];
      EXPECT_EQ(c.windows, windows) << r.label << ", " << c.verdict;
      // The table prints whole percents; the record three decimals.
      EXPECT_LE(std::fabs(100 * c.u1 - u1), 0.5 + 1e-9) << r.label << ", " << c.verdict;
      EXPECT_LE(std::fabs(100 * c.u0 - u0), 0.5 + 1e-9) << r.label << ", " << c.verdict;
    }
  }
}

}  // namespace
}  // namespace gridfree
