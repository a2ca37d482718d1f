// SPDX-License-Identifier: GPL-3.0-or-later
// parse_job / parse_case / read_json_file: the contract's job parses into
// the expected values (defaults filled in), semantic errors are collected
// with their JSON pointers, malformed JSON names file:line:col.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "job/case_grid.h"
#include "job/job_spec.h"
#include "job/particles_spec.h"
#include "contract_job.h"

namespace gridfree {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Problems of an invalid job (the test fails if it parses).
std::vector<Problem> problems_of(const json& doc, const fs::path& base = ".") {
  try {
    parse_job(doc, base);
  } catch (const InputError& e) {
    return e.problems();
  }
  ADD_FAILURE() << "the job parsed";
  return {};
}

bool has_problem(const std::vector<Problem>& problems, const std::string& where) {
  return std::any_of(problems.begin(), problems.end(), [&](const Problem& p) { return p.where == where; });
}

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("gridfree_job_test_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

TEST(ParseJob, ContractJob) {
  const JobSpec job = parse_job(test::contract_job(), ".");
  const CaseSpec& c = job.case_spec;
  EXPECT_EQ(c.name, "PC1");
  EXPECT_EQ(c.domain_dp, (std::array<double, 3>{30, 200, 10}));
  EXPECT_DOUBLE_EQ(c.particle_diameter_cm, 0.01);
  EXPECT_TRUE(c.periodic(0));
  EXPECT_FALSE(c.periodic(1));
  EXPECT_TRUE(c.periodic(2));
  EXPECT_EQ(c.boundaries[1][0].kind, BoundaryKind::kMassInflow);
  EXPECT_DOUBLE_EQ(c.boundaries[1][0].superficial_velocity_cm_s, 20.0);
  EXPECT_EQ(c.boundaries[1][1].kind, BoundaryKind::kPressureOutflow);
  const auto* g = std::get_if<GeneratorSpec>(&c.particles);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->kind, "bursting_bubble");
  EXPECT_EQ(g->where, "/case/particles/generator");
  EXPECT_EQ(job.numerics.cells, (std::array<int, 3>{30, 200, 10}));
  EXPECT_EQ(job.numerics.convection, Limiter::kSuperbee);
  EXPECT_EQ(job.numerics.drag, DragLaw::kBvk);
  EXPECT_EQ(job.numerics.deposition.kind, DepositionKind::kDiffusion);
  EXPECT_DOUBLE_EQ(job.numerics.deposition.fwhm_dp, 6);
  EXPECT_EQ(job.numerics.max_iterations, 20000);
  // The job records its transfer expanded (presets and defaults written out).
  nlohmann::json expected = test::contract_job();
  expected["numerics"]["deposition"] = {{"kind", "diffusion"},        {"fwhm_dp", 6.0},          {"pre_deposition", "trilinear"},
                                        {"sampling", "trilinear"},    {"diffusivity", "consistent"}, {"integration", "exact"}};
  EXPECT_EQ(job.source, expected);
}

TEST(ParseJob, DefaultsForOptionalFields) {
  json j = test::contract_job();
  j["case"].erase("gravity_cm_s2");
  j["case"].erase("particle_velocity");
  j["case"].erase("probes");
  j["numerics"].erase("tolerances");
  j["numerics"].erase("max_iterations");
  j["numerics"]["deposition"] = {{"kind", "diffusion"}, {"fwhm_dp", 4}, {"diffusivity", "mfix"}};
  j["numerics"]["grid"] = {{"delta_star", 2.0}};
  const JobSpec job = parse_job(j, ".");
  EXPECT_EQ(job.case_spec.gravity_cm_s2, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(job.case_spec.particle_velocity.thermal_cm_s, 0);
  EXPECT_EQ(job.case_spec.probes.y1_dp, 4);
  EXPECT_EQ(job.case_spec.probes.y2_dp, 104);
  EXPECT_EQ(job.numerics.tolerances.linear, 1e-2);
  EXPECT_EQ(job.numerics.tolerances.filter, 1e-10);
  EXPECT_EQ(job.numerics.tolerances.steady, 1e-5);
  EXPECT_EQ(job.numerics.max_iterations, 20000);
  EXPECT_EQ(job.numerics.deposition.diffusivity, FilterDiffusivity::kMfix);
  // round(L*/Δ*) per direction: 30/2, 200/2, 10/2.
  EXPECT_EQ(job.numerics.cells, (std::array<int, 3>{15, 100, 5}));
}

TEST(ParseJob, ProbesMustLieInsideTheDomain) {
  json j = test::contract_job();
  j["case"]["probes"]["pressure_drop"] = {{"y1_dp", 4}, {"y2_dp", 250}};
  auto problems = problems_of(j);
  ASSERT_EQ(problems.size(), 1u) << format_problems(problems);
  EXPECT_EQ(problems[0].where, "/case/probes/pressure_drop/y2_dp");

  j["case"]["probes"]["pressure_drop"] = {{"y1_dp", 0}, {"y2_dp", 104}};
  EXPECT_TRUE(has_problem(problems_of(j), "/case/probes/pressure_drop/y1_dp"));
  j["case"]["probes"]["pressure_drop"] = {{"y1_dp", 104}, {"y2_dp", 4}};
  EXPECT_TRUE(has_problem(problems_of(j), "/case/probes/pressure_drop/y2_dp"));
}

TEST(ParseJob, OneCellAlongTheFlowAndAFilterWiderThanTheDomainAreRefused) {
  json j = test::contract_job();
  j["numerics"]["grid"] = {{"cells", {1, 1, 1}}};
  EXPECT_TRUE(has_problem(problems_of(j), "/numerics/grid"));
  j["numerics"]["grid"] = {{"delta_star", 1000}};
  EXPECT_TRUE(has_problem(problems_of(j), "/numerics/grid"));
  j["numerics"]["grid"] = {{"cells", {15, 100, 5}}};
  j["numerics"]["deposition"] = {{"kind", "diffusion"}, {"fwhm_dp", 1e300}};
  EXPECT_TRUE(has_problem(problems_of(j), "/numerics/deposition/fwhm_dp"));
}

// A uniform bed without particles (φ = 0) has no drag and nothing to verify:
// refused at its pointer instead of running to not_converged.
TEST(ParseJob, AUniformBedWithoutParticlesIsRefused) {
  json j = test::contract_job();
  j["case"]["particles"] = {{"uniform", {{"solids_fraction", 0}}}};
  const auto problems = problems_of(j);
  ASSERT_EQ(problems.size(), 1u) << format_problems(problems);
  EXPECT_EQ(problems[0].where, "/case/particles/uniform/solids_fraction");
  EXPECT_NE(problems[0].reason.find("> 0"), std::string::npos) << problems[0].reason;
  j["case"]["particles"] = {{"uniform", {{"solids_fraction", 1e-3}}}};
  EXPECT_NO_THROW(parse_job(j, "."));
}

TEST(ParseJob, StallWindowIsReadAndOutOfRangeRefused) {
  json j = test::contract_job();
  j["numerics"]["stall_window"] = 250;
  EXPECT_EQ(parse_job(j, ".").numerics.stall_window, 250);
  j["numerics"]["stall_window"] = 0;
  EXPECT_EQ(parse_job(j, ".").numerics.stall_window, 0);
  for (const json& bad : {json(-1), json(2.5), json("long"), json(2000000000)}) {
    j["numerics"]["stall_window"] = bad;
    EXPECT_TRUE(has_problem(problems_of(j), "/numerics/stall_window")) << bad;
  }
}

TEST(ParseJob, StallRemedyIsReadAndNeedsAStallWindow) {
  json j = test::contract_job();
  EXPECT_FALSE(parse_job(j, ".").numerics.relax_stalled_correction);
  j["numerics"]["stall_window"] = 200;
  j["numerics"]["stall_remedy"] = "relax_correction";
  EXPECT_TRUE(parse_job(j, ".").numerics.relax_stalled_correction);
  j["numerics"]["stall_remedy"] = "none";
  EXPECT_FALSE(parse_job(j, ".").numerics.relax_stalled_correction);
  j["numerics"]["stall_remedy"] = "freeze_limiter";
  EXPECT_TRUE(has_problem(problems_of(j), "/numerics/stall_remedy"));
  j["numerics"]["stall_remedy"] = "relax_correction";
  j["numerics"]["stall_window"] = 0;  // the remedy acts when the stall rule fires
  EXPECT_TRUE(has_problem(problems_of(j), "/numerics/stall_remedy"));
}

TEST(ParseJob, CollectsSemanticProblemsTogether) {
  json j = test::contract_job();
  j["case"]["probes"]["pressure_drop"]["y2_dp"] = 300;                       // outside L_y* = 200
  j["case"]["boundaries"]["y_high"] = {{"type", "mass_inflow"}, {"superficial_velocity_cm_s", 1}};
  j["case"]["particles"] = {{"file", "missing_particles.csv"}, {"format", "csv"}};
  const auto problems = problems_of(j);
  EXPECT_EQ(problems.size(), 3u) << format_problems(problems);
  EXPECT_TRUE(has_problem(problems, "/case/probes/pressure_drop/y2_dp"));
  EXPECT_TRUE(has_problem(problems, "/case/boundaries/y_high/type"));
  EXPECT_TRUE(has_problem(problems, "/case/particles/file"));
}

TEST(ParseJob, SchemaProblemsComeFirst) {
  json j = test::contract_job();
  j["case"]["domain_dp"][0] = -30;
  const auto problems = problems_of(j);
  ASSERT_EQ(problems.size(), 1u) << format_problems(problems);
  EXPECT_EQ(problems[0].where, "/case/domain_dp/0");
}

TEST(ParseJob, GeneratorParametersAgainstTheDomain) {
  json j = test::contract_job();
  j["case"]["domain_dp"] = {10, 200, 10};  // the bursting bubble needs L_x* >= 20
  EXPECT_TRUE(has_problem(problems_of(j), "/case/particles/generator/kind"));

  j = test::contract_job();
  j["case"]["particles"]["generator"] = {{"kind", "uniform_random"}, {"seed", 1}, {"solids_fraction", 0.5}};
  auto problems = problems_of(j);
  ASSERT_EQ(problems.size(), 1u) << format_problems(problems);
  EXPECT_EQ(problems[0].where, "/case/particles/generator/solids_fraction");

  j["case"]["particles"]["generator"] = {{"kind", "uniform_random"}, {"seed", 1}, {"solids_fraction", 0.2},
                                         {"region_dp", {{"min", {0, 0, 0}}, {"max", {30, 300, 10}}}}};
  EXPECT_TRUE(has_problem(problems_of(j), "/case/particles/generator/region_dp"));

  j["case"]["particles"]["generator"] = {{"kind", "sscp_like"}, {"seed", 1}, {"bed_height_dp", 50},
                                         {"solids_fraction", 0.58}, {"bubbles", 2}, {"bubble_radius_dp", 40}};
  EXPECT_TRUE(has_problem(problems_of(j), "/case/particles/generator/bubble_radius_dp"));
}

TEST(ParseJob, RelativeParticleFileResolvesAgainstTheJobFolder) {
  TempDir dir;
  std::ofstream(dir.path() / "bed.csv") << "x,y,z,d\n0.05,0.05,0.05,0.01\n";
  json j = test::contract_job();
  j["case"]["particles"] = {{"file", "bed.csv"}, {"format", "csv"}};
  std::ofstream(dir.path() / "job.json") << j.dump(2);
  const JobSpec job = parse_job_file(dir.path() / "job.json");
  const auto* f = std::get_if<FileSpec>(&job.case_spec.particles);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->path, dir.path() / "bed.csv");
  EXPECT_EQ(f->format, "csv");
}

TEST(ReadJsonFile, MalformedJsonNamesLineAndColumn) {
  TempDir dir;
  const fs::path file = dir.path() / "broken.json";
  // Line 3, column 12 is the 'x' where a value should start ("  \"b\": [1, x]").
  std::ofstream(file) << "{\n  \"a\": 1,\n  \"b\": [1, x]\n}\n";
  try {
    read_json_file(file);
    FAIL() << "parsed malformed JSON";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].where, file.string() + ":3:12");
    EXPECT_NE(e.problems()[0].reason.find("invalid JSON"), std::string::npos);
  }
  EXPECT_THROW(read_json_file(dir.path() / "absent.json"), InputError);
}

TEST(CaseGrid, DomainInCentimetresAndPeriodicFlags) {
  const JobSpec job = parse_job(test::contract_job(), ".");
  const Grid g = make_grid(job.case_spec, {15, 100, 5});
  EXPECT_EQ(g.n, (std::array<int, 3>{15, 100, 5}));
  EXPECT_DOUBLE_EQ(g.length[0], 0.30);
  EXPECT_DOUBLE_EQ(g.length[1], 2.00);
  EXPECT_DOUBLE_EQ(g.length[2], 0.10);
  EXPECT_EQ(g.periodic, (std::array<bool, 3>{true, false, true}));
  EXPECT_NEAR(g.delta_star(0.01), 2.0, 1e-12);
}

TEST(ParticlesSpec, DefaultsAndErrors) {
  const CaseSpec c = parse_particles_spec(
      json::parse(R"({"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
                      "generator": {"kind": "bursting_bubble", "seed": 3},
                      "particle_velocity": {"thermal_cm_s": 1.0, "seed": 7}})"),
      ".");
  EXPECT_TRUE(c.periodic(0));
  EXPECT_TRUE(c.periodic(2));
  EXPECT_EQ(c.particle_velocity.seed, 7u);
  const CaseSpec s = parse_particles_spec(
      json::parse(R"({"domain_dp": [70, 370, 23], "particle_diameter_cm": 0.3256,
                      "generator": {"kind": "sscp_like", "seed": 1, "bed_height_dp": 50,
                                    "solids_fraction": 0.58, "bubbles": 3, "bubble_radius_dp": 5}})"),
      ".");
  EXPECT_FALSE(s.periodic(0));  // SSCP-I has walls
  try {
    parse_particles_spec(json::parse(R"({"domain_dp": [-30, 200, 10], "particle_diameter_cm": 0.01,
                                         "generator": {"kind": "bursting", "seed": 1}})"),
                         ".");
    FAIL() << "accepted a bad spec";
  } catch (const InputError& e) {
    EXPECT_TRUE(has_problem(e.problems(), "/domain_dp/0"));
    EXPECT_TRUE(has_problem(e.problems(), "/generator/kind"));
  }
}

}  // namespace
}  // namespace gridfree
