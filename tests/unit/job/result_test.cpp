// SPDX-License-Identifier: GPL-3.0-or-later
// The result document: what to_json writes validates against
// schemas/result.schema.json and reads back field for field.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/schema_validation.h"
#include "job/result.h"
#include "particles/bed_summary.h"

namespace gridfree {
namespace {

JobResult example() {
  JobResult r;
  r.job_hash = std::string(64, 'a');
  r.status = SolveStatus::kConverged;
  r.dp_star = 1158.8;
  r.cells = {30, 200, 10};
  r.delta_star = 1.0;
  r.iterations = 412;
  r.residual_continuity = 8e-6;
  r.residual_momentum = 3e-6;
  r.dp_star_change = 1e-7;
  r.wall_s = 3.2;
  r.cpu_s = 6.1;
  r.peak_rss_mb = 85;
  r.particles = 4649;
  r.max_solids_fraction = 0.41;
  r.mass_imbalance = 1e-9;
  r.extra = {{"filter", {{"iterations", 12}}}};
  r.version = "gridfree 0.1.0 (abc)";
  return r;
}

TEST(Result, RoundTrip) {
  const JobResult r = example();
  const nlohmann::json j = to_json(r);
  EXPECT_TRUE(validate_against_schema(j, "result.schema").empty()) << format_problems(validate_against_schema(j, "result.schema"));
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["srq"]["dp_star"], 1158.8);
  EXPECT_EQ(j["diagnostics"]["particles"], 4649);
  const JobResult back = result_from_json(j);
  EXPECT_EQ(back.job_hash, r.job_hash);
  EXPECT_EQ(back.status, r.status);
  EXPECT_EQ(back.dp_star, r.dp_star);
  EXPECT_EQ(back.cells, r.cells);
  EXPECT_EQ(back.iterations, r.iterations);
  EXPECT_EQ(back.residual_continuity, r.residual_continuity);
  EXPECT_EQ(back.residual_momentum, r.residual_momentum);
  EXPECT_EQ(back.dp_star_change, r.dp_star_change);
  EXPECT_EQ(back.wall_s, r.wall_s);
  EXPECT_EQ(back.cpu_s, r.cpu_s);
  EXPECT_EQ(back.peak_rss_mb, r.peak_rss_mb);
  EXPECT_EQ(back.particles, r.particles);
  EXPECT_EQ(back.max_solids_fraction, r.max_solids_fraction);
  EXPECT_EQ(back.mass_imbalance, r.mass_imbalance);
  EXPECT_EQ(back.extra, r.extra);
  EXPECT_EQ(back.version, r.version);
}

// A result with the bed's summary (particles/bed_summary.h) of a simple
// cubic lattice validates, reads back unchanged, and says `ordered`.
TEST(Result, BedSummaryValidatesAndReadsBack) {
  std::vector<Particle> lattice;
  const double d = 0.1, a = 1.25 * d;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) lattice.push_back({(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a, d, 0, 0, 0});
  const std::array<double, 3> box{8 * a, 8 * a, 8 * a};
  JobResult r = example();
  r.bed = bed_summary(bed_structure(lattice, box, {true, false, true}), lattice, box);
  r.bed["cpu_s"] = 0.01;
  const nlohmann::json j = to_json(r);
  const auto problems = validate_against_schema(j, "result.schema");
  EXPECT_TRUE(problems.empty()) << format_problems(problems);
  EXPECT_TRUE(j.at("bed").at("ordered").get<bool>()) << j.at("bed").dump();
  EXPECT_EQ(result_from_json(j).bed, r.bed);
  // A misspelt field is refused by the schema.
  nlohmann::json bad = j;
  bad["bed"]["orderd"] = true;
  EXPECT_FALSE(validate_against_schema(bad, "result.schema").empty());
  // Without a bed (a continuum bed): no key at all.
  r.bed = nullptr;
  EXPECT_FALSE(to_json(r).contains("bed"));
}

TEST(Result, DivergedRunWritesNullsForNonFiniteNumbers) {
  JobResult r = example();
  r.status = SolveStatus::kDiverged;
  r.reason = "residual grew above 1e10";
  r.dp_star.reset();
  r.residual_momentum = std::numeric_limits<double>::infinity();
  r.residual_continuity = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json j = to_json(r);
  EXPECT_TRUE(validate_against_schema(j, "result.schema").empty());
  EXPECT_TRUE(j["srq"]["dp_star"].is_null());
  EXPECT_TRUE(j["residuals"]["momentum"].is_null());
  EXPECT_EQ(j["reason"], "residual grew above 1e10");
  const JobResult back = result_from_json(nlohmann::json::parse(j.dump()));
  EXPECT_FALSE(back.dp_star.has_value());
  EXPECT_TRUE(std::isnan(back.residual_momentum));
  EXPECT_EQ(back.status, SolveStatus::kDiverged);
}

// The outcome word splits not_converged by what stopped the iterations
// (docs/INTERFACE.md §2): the stall window or the iteration cap.
TEST(Result, OutcomeSplitsNotConvergedIntoStalledAndIterationCap) {
  JobResult r = example();
  EXPECT_EQ(to_json(r)["outcome"], "converged");
  r.status = SolveStatus::kNotConverged;
  r.reason = "not converged after 20000 iterations";
  EXPECT_EQ(to_json(r)["outcome"], "iteration_cap");
  r.stalled = true;
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["outcome"], "stalled");
  EXPECT_TRUE(validate_against_schema(j, "result.schema").empty()) << format_problems(validate_against_schema(j, "result.schema"));
  EXPECT_TRUE(result_from_json(j).stalled);
  for (const auto s : {SolveStatus::kDiverged, SolveStatus::kInvalid, SolveStatus::kFailed}) {
    r.status = s;
    r.dp_star.reset();
    EXPECT_EQ(to_json(r)["outcome"], solve_status_name(s));
  }
}

TEST(Result, StatusNames) {
  for (SolveStatus s : {SolveStatus::kConverged, SolveStatus::kNotConverged, SolveStatus::kDiverged,
                        SolveStatus::kInvalid, SolveStatus::kFailed})
    EXPECT_EQ(solve_status_from_name(solve_status_name(s)), s);
  EXPECT_EQ(solve_status_name(SolveStatus::kNotConverged), "not_converged");
  EXPECT_FALSE(solve_status_from_name("done").has_value());
}

TEST(Result, MalformedDocumentIsAnInputError) {
  nlohmann::json j = to_json(example());
  j["status"] = "finished";
  try {
    result_from_json(j);
    FAIL() << "accepted a bad status";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].where, "/status");
  }
}

}  // namespace
}  // namespace gridfree
