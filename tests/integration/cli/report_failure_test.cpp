// `gridfree run` when the report cannot be written (its folder cannot be
// created: a file is in the way): exit 1, no report path printed, the
// results still in the database; and a temporary report file left by a
// killed writer is removed by the next run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
const fs::path kSource = GRIDFREE_SOURCE_DIR;
const fs::path kFake = kSource / "tests/fixtures/fake_worker.sh";

using gridfree::test_support::shell_quote;
std::string quote(const std::string& s) { return shell_quote(s); }

fs::path study_file(const fs::path& dir) {
  std::ifstream in(kSource / "studies/quickstart.json");
  auto doc = nlohmann::json::parse(in);
  doc["name"] = "reportless";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"ok", pc1}};
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3}}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  return dir / "study.json";
}

gridfree::test_support::CommandRun run(const fs::path& dir, const std::string& args) {
  return gridfree::test_support::run_command("cd " + quote(dir.string()) + " && GRIDFREE_WORKER=" +
                                                 quote(kFake.string()) + " " +
                                                 quote(std::string(GRIDFREE_BIN_DIR) + "/gridfree") + " " + args,
                                             dir / "stderr.txt");
}

TEST(ReportFailure, RunExitsNonZeroAndNamesNoMissingFile) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("report_failure", "blocked");
  std::ofstream(dir / "blocker") << "a file where the report folder should go\n";
  const auto r = run(dir, "run " + quote(study_file(dir).string()) + " --db g.sqlite --out " +
                              quote((dir / "blocker" / "report").string()));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.find("report.html"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("report: not written"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "g.sqlite"));
}

TEST(ReportFailure, TempFilesOfAKilledWriterAreRemoved) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("report_failure", "stale");
  const auto out = dir / "out";
  fs::create_directories(out);
  // pid 2^22 + 1 is above Linux's largest pid (4194304): no such process.
  const auto stale = out / ".report.html.tmp-4194305-1";
  std::ofstream(stale) << "half a report";
  const auto r = run(dir, "run " + quote(study_file(dir).string()) + " --db g.sqlite --out " + quote(out.string()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_FALSE(fs::exists(stale));
}

}  // namespace
