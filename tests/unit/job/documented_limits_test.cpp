// SPDX-License-Identifier: GPL-3.0-or-later
// The documented limits are the code's: docs/LIMITS.md's memory model and
// inflow-velocity range and INTERFACE.md's y_low row read back and compared
// with job/memory_estimate.h and job/case_plausibility.h.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "job/case_plausibility.h"
#include "job/memory_estimate.h"
#include "project_paths.h"

namespace gridfree {
namespace {

std::string doc_text(const char* name) {
  std::ifstream in(test_support::kSourceDir / "docs" / name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DocumentedLimits, MemoryModelIsTheCodes) {
  const std::string limits = doc_text("LIMITS.md");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(limits, m, std::regex(R"(estimate = (\d+) bytes per cell \+ 64 MiB)")));
  EXPECT_EQ(std::stod(m[1].str()), kWorkerBytesPerCell);
  EXPECT_EQ(kWorkerBaseBytes, 64.0 * 1024 * 1024);
}

TEST(DocumentedLimits, InflowVelocityRangeIsTheCodes) {
  const std::string limits = doc_text("LIMITS.md");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(limits, m, std::regex(R"(\| `superficial_velocity_cm_s` \| (\S+) … (\S+) cm/s)")));
  EXPECT_EQ(std::stod(m[1].str()), kInflowRange.low);
  EXPECT_EQ(std::stod(m[2].str()), kInflowRange.high);
  const std::string interface = doc_text("INTERFACE.md");
  EXPECT_NE(interface.find("| `case.boundaries.y_low` | `{\"type\": \"mass_inflow\""), std::string::npos);
  ASSERT_TRUE(std::regex_search(interface, m, std::regex(R"((\S+) ≤ U₀ ≤ (\S+) cm/s)")));
  EXPECT_EQ(std::stod(m[1].str()), kInflowRange.low);
  EXPECT_EQ(std::stod(m[2].str()), kInflowRange.high);
  EXPECT_EQ(interface.find("U0 ≥ 0"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
