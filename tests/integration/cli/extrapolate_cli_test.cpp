// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree extrapolate` as users run it: a JSON and a CSV series in, the
// docs/INTERFACE.md §4 JSON out on stdout with exit 0; invalid input exits 2 with a
// message on stderr naming the problem.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"

namespace {

namespace fs = std::filesystem;

using gridfree::test_support::CommandRun;

CommandRun run_gridfree(const std::string& args, const fs::path& dir) {
  return gridfree::test_support::run_executable("gridfree", args, dir);
}

class ExtrapolateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("gridfree_extrapolate_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

// f = 2 + 0.5 h on 5 grids: exact first order, so f0 = 2 and p = 1.
const char* kJsonSeries = R"({"h": [0.5, 1, 2, 4, 8], "f": [2.25, 2.5, 3, 4, 6]})";
const char* kCsvSeries = "h,f\n8,6\n4,4\n2,3\n1,2.5\n0.5,2.25\n";

TEST_F(ExtrapolateCli, JsonSeriesPrintsTheContractJson) {
  const CommandRun r = run_gridfree("extrapolate " + write("s.json", kJsonSeries).string(), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["method"], "power");
  EXPECT_NEAR(j["f0"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(j["p"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(j["grids"].size(), 5u);
  EXPECT_EQ(j["gci"].size(), 3u);
  EXPECT_NE(r.out.find("\n  \"status\""), std::string::npos) << "pretty-printed, 2-space indent";
}

TEST_F(ExtrapolateCli, CsvSeriesGivesTheSameAnswer) {
  const CommandRun a = run_gridfree("extrapolate " + write("s.json", kJsonSeries).string(), dir_);
  const CommandRun b = run_gridfree("extrapolate " + write("s.csv", kCsvSeries).string(), dir_);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(nlohmann::json::parse(a.out), nlohmann::json::parse(b.out));
}

TEST_F(ExtrapolateCli, MethodAndPRangeOptions) {
  const auto file = write("s.json", kJsonSeries).string();
  const CommandRun eh = run_gridfree("extrapolate " + file + " --method eh14", dir_);
  ASSERT_EQ(eh.exit_code, 0) << eh.err;
  const auto j = nlohmann::json::parse(eh.out);
  EXPECT_EQ(j["method"].get<std::string>().rfind("eh14_power", 0), 0u);
  EXPECT_TRUE(j.contains("eh14"));
  const CommandRun narrow = run_gridfree("extrapolate " + file + " --p-range 1.5 2", dir_);
  ASSERT_EQ(narrow.exit_code, 0) << narrow.err;
  EXPECT_EQ(nlohmann::json::parse(narrow.out)["method"], "mixed");  // p = 1 not accepted
}

TEST_F(ExtrapolateCli, InvalidInputExitsTwo) {
  struct Case {
    std::string name, text, expect_in_stderr;
  };
  for (const Case& c : {Case{"dup.json", R"({"h": [1, 2, 2, 4], "f": [1, 2, 3, 4]})", "/h/2"},
                        Case{"nan.csv", "h,f\n1,2\n2,nan\n3,4\n4,5\n", "nan.csv:3"},
                        Case{"neg.json", R"({"h": [1, -2, 3, 4], "f": [1, 2, 3, 4]})", "/h/1"},
                        Case{"short.json", R"({"h": [1, 2, 3], "f": [1, 2]})", "/f"},
                        Case{"broken.json", R"({"h": [1, 2)", "invalid JSON"}}) {
    const CommandRun r = run_gridfree("extrapolate " + write(c.name, c.text).string(), dir_);
    EXPECT_EQ(r.exit_code, 2) << c.name;
    EXPECT_NE(r.err.find(c.expect_in_stderr), std::string::npos) << c.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name;
  }
  EXPECT_EQ(run_gridfree("extrapolate " + (dir_ / "missing.json").string(), dir_).exit_code, 2);
  const auto file = write("s.json", kJsonSeries).string();
  EXPECT_EQ(run_gridfree("extrapolate " + file + " --method gci", dir_).exit_code, 2);
  EXPECT_EQ(run_gridfree("extrapolate " + file + " --p-range 2 1", dir_).exit_code, 2);
  EXPECT_EQ(run_gridfree("extrapolate " + file + " --order 0", dir_).exit_code, 2);
  EXPECT_EQ(run_gridfree("extrapolate " + file + " --order -1", dir_).exit_code, 2);
}

// f = 2 + 0.5 h on 7 grids h = 0.25 … 16: exact first order. Declared second
// order, the data contradict it: not converged, and the output says which
// method, order and measured coverage it reports.
TEST_F(ExtrapolateCli, ADeclaredOrderTheDataContradictIsNotConverged) {
  const auto file =
      write("s.json", R"({"h": [0.25, 0.5, 1, 2, 4, 8, 16], "f": [2.125, 2.25, 2.5, 3, 4, 6, 10]})").string();
  const auto plain = nlohmann::json::parse(run_gridfree("extrapolate " + file, dir_).out);
  EXPECT_EQ(plain["coverage"]["method"], "averaged");  // the default
  EXPECT_EQ(plain["coverage"]["order_declared"], false);
  EXPECT_TRUE(plain["bias_checks"]["order_consistent"].is_null());
  EXPECT_EQ(plain["bias_checks"]["leave_one_out_agree"], true);
  const CommandRun r = run_gridfree("extrapolate " + file + " --order 2", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["verdict"]["value"], "converged");
  EXPECT_EQ(j["bias_checks"]["order_consistent"], false);
  EXPECT_NEAR(j["bias_checks"]["order_ratio"].get<double>(), 0.5, 1e-8);
  EXPECT_EQ(j["coverage"]["order_declared"], true);
  EXPECT_TRUE(j["coverage"]["classes"].contains("converged"));
  const CommandRun same = run_gridfree("extrapolate " + file + " --order 1", dir_);
  EXPECT_EQ(nlohmann::json::parse(same.out)["bias_checks"]["order_consistent"], true);
  const CommandRun before = run_gridfree("extrapolate " + file + " --method capped --no-leave-one-out", dir_);
  EXPECT_TRUE(nlohmann::json::parse(before.out)["bias_checks"]["leave_one_out_agree"].is_null());
}

}  // namespace
