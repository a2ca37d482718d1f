// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile input to both executables (docs/LIMITS.md): the corpus in
// tests/fixtures/hostile/ (studies and jobs: overflowing numbers, bad UTF-8,
// zero inflow, Δ* = 1e-300, a domain of 1e300, implausible properties, ...)
// and generated extremes (100 000-deep nesting, a 30 000-character name,
// 20 000 coincident particles). Each is refused with exit 2 and a message
// naming the JSON pointer or file:line:column, in bounded time, and leaves an
// existing database exactly as it was and writes no result.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "contract_job.h"
#include "project_paths.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::kSourceDir;
const fs::path kCorpus = kSourceDir / "tests/fixtures/hostile";

using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;

// Runs and measures; the bound is generous against machine load but far below
// the minutes the unbounded checks took.
CommandRun timed(const std::string& exe, const std::string& args, const fs::path& dir, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  CommandRun r = gridfree::test_support::run_executable(exe, args + " </dev/null", dir);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

constexpr double kBoundSeconds = 10.0;
// At most 20 listed problems (ParticleCheckOptions::max_problems) of a few
// hundred characters each (two file paths and the distances).
constexpr std::size_t kMaxMessageBytes = 8000;

std::string database_state(const fs::path& db) {
  return sqlite_query(
      db, "SELECT COUNT(*), MAX(id) FROM studies; SELECT COUNT(*) FROM jobs; SELECT COUNT(*) FROM results;");
}

class HostileInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = gridfree::test_support::fresh_scratch_dir("hostile", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  // A job refused by `gridfree-worker solve`: exit 2, `expect` in the message, no result file.
  void expect_job_refused(const fs::path& job, const std::string& expect, const std::string& extra = "") {
    double seconds = 0;
    const fs::path out = dir_ / "result.json";
    const auto r =
        timed("gridfree-worker", "solve " + shell_quote(job.string()) + " -o " + shell_quote(out.string()) + extra,
              dir_, seconds);
    EXPECT_EQ(r.exit_code, 2) << job.filename() << "\n" << r.err.substr(0, 2000);
    EXPECT_NE(r.err.find(expect), std::string::npos) << job.filename() << " should name " << expect << ":\n"
                                                     << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), kMaxMessageBytes) << job.filename() << ": unbounded message";
    EXPECT_LT(seconds, kBoundSeconds) << job.filename();
    EXPECT_FALSE(fs::exists(out)) << job.filename();
  }
  // A study refused by validate and by run on an existing database, which stays as it was.
  void expect_study_refused(const fs::path& study, const std::string& expect) {
    const fs::path db = dir_ / "existing.sqlite";
    if (!fs::exists(db)) {
      std::ifstream in(kSourceDir / "tests/fixtures/hostile/studies/huge_density.json");
      auto good = nlohmann::json::parse(in);
      good["name"] = "good";
      good["cases"]["PC1"]["gas"]["density_g_cm3"] = 0.001;
      const auto file = write("good.json", good.dump());
      ASSERT_EQ(gridfree::test_support::run_executable("gridfree", "submit " + shell_quote(file.string()) + " --db " +
                                                                       shell_quote(db.string()), dir_).exit_code, 0);
    }
    const std::string before = database_state(db);
    for (const std::string cmd : {"validate ", "run "}) {
      const std::string db_arg = cmd == "run " ? " --db " + shell_quote(db.string()) : "";
      double seconds = 0;
      const auto r = timed("gridfree", cmd + shell_quote(study.string()) + db_arg, dir_, seconds);
      EXPECT_EQ(r.exit_code, 2) << cmd << study.filename() << "\n" << r.err.substr(0, 2000);
      EXPECT_NE(r.err.find(expect), std::string::npos) << cmd << study.filename() << " should name " << expect
                                                       << ":\n" << r.err.substr(0, 2000);
      EXPECT_LT(r.err.size(), kMaxMessageBytes) << study.filename() << ": unbounded message";
      EXPECT_LT(seconds, kBoundSeconds) << cmd << study.filename();
    }
    EXPECT_EQ(database_state(db), before) << study.filename();
    EXPECT_FALSE(fs::exists(dir_ / "gridfree.sqlite"));
  }
  fs::path dir_;
};

TEST_F(HostileInput, JobCorpus) {
  std::ifstream in(kCorpus / "jobs/expected.json");
  const auto expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 8u);
  for (const auto& [file, expect] : expected.items()) expect_job_refused(kCorpus / file, expect.get<std::string>());
}

TEST_F(HostileInput, StudyCorpus) {
  std::ifstream in(kCorpus / "studies/expected.json");
  const auto expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 10u);
  for (const auto& [file, expect] : expected.items()) expect_study_refused(kCorpus / file, expect.get<std::string>());
}

TEST_F(HostileInput, DeepNestingIsRefusedWithoutRecursion) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  auto job = gridfree::test::contract_job().dump();
  job.replace(job.find("\"schema\""), 0, "\"deep\": " + deep + ", ");
  expect_job_refused(write("deep_job.json", job), "deep_job.json:1:");
  std::ifstream in(kCorpus / "studies/huge_density.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string study = text.str();
  study.replace(study.find("\"schema\""), 0, "\"deep\": " + deep + ",\n");
  expect_study_refused(write("deep_study.json", study), "deep_study.json:2:");
}

TEST_F(HostileInput, LongNamesAreRefusedWithAShortQuote) {
  std::ifstream in(kCorpus / "studies/huge_density.json");
  auto study = nlohmann::json::parse(in);
  study["cases"]["PC1"]["gas"]["density_g_cm3"] = 0.001;
  study["name"] = std::string(30000, 'x') + "!";
  expect_study_refused(write("long_name.json", study.dump()), "/name");
}

TEST_F(HostileInput, WorkerMemoryLimit) {
  auto job = gridfree::test::contract_job();
  job["numerics"]["grid"] = {{"cells", {300, 2000, 100}}};  // 6e7 cells: about 22 GiB estimated
  expect_job_refused(write("big.json", job.dump()), "/numerics/grid", " --max-memory 1G");
  job["numerics"]["grid"] = {{"cells", {30, 200, 10}}};
  expect_job_refused(write("small.json", job.dump()), "--max-memory", " --max-memory lots");
}

TEST_F(HostileInput, CoincidentParticlesAreRejectedQuickly) {
  std::ostringstream csv;
  csv << "x,y,z,d\n";
  for (int i = 0; i < 20000; ++i) csv << "0.1,0.5,0.05,0.01\n";
  write("bed.csv", csv.str());
  auto job = gridfree::test::contract_job();
  job["case"]["particles"] = {{"file", "bed.csv"}, {"format", "csv"}};
  expect_job_refused(write("coincident.json", job.dump()), "bed.csv:");
}

}  // namespace
