// SPDX-License-Identifier: GPL-3.0-or-later
// Input validation, sorting, weights and file parsing of a series.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "extrap/series.h"
#include "extrap/series_io.h"

namespace gridfree {
namespace {

// Throws InputError and one of its problems is at `where` with `reason_part` in the reason.
void expect_problem(const std::function<void()>& fn, const std::string& where, const std::string& reason_part) {
  try {
    fn();
    FAIL() << "expected InputError at " << where;
  } catch (const InputError& e) {
    bool found = false;
    for (const auto& p : e.problems())
      found = found || (p.where == where && p.reason.find(reason_part) != std::string::npos);
    EXPECT_TRUE(found) << "problems were:\n" << e.what();
  }
}

TEST(ExtrapSeries, SortsByCellSizeKeepingPairs) {
  const Series s = make_series({2.0, 0.5, 1.0}, {20, 5, 10});
  EXPECT_EQ(s.h, (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(s.f, (std::vector<double>{5, 10, 20}));
}

TEST(ExtrapSeries, RejectsDuplicateCellSize) {
  expect_problem([] { make_series({1.0, 2.0, 1.0, 3.0}, {1, 2, 3, 4}); }, "/h/2", "duplicate");
}

TEST(ExtrapSeries, RejectsNanAndInfinity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expect_problem([&] { make_series({1, 2, 3, 4}, {1, nan, 3, 4}); }, "/f/1", "finite");
  expect_problem([&] { make_series({1, inf, 3, 4}, {1, 2, 3, 4}); }, "/h/1", "finite");
}

TEST(ExtrapSeries, RejectsNonPositiveCellSize) {
  expect_problem([] { make_series({1, 0, 3, 4}, {1, 2, 3, 4}); }, "/h/1", "positive");
  expect_problem([] { make_series({1, -2, 3, 4}, {1, 2, 3, 4}); }, "/h/1", "positive");
}

TEST(ExtrapSeries, RejectsMismatchedLengthsAndTooFewValues) {
  expect_problem([] { make_series({1, 2, 3}, {1, 2}); }, "/f", "3");
  expect_problem([] { make_series({1}, {1}); }, "/h", "at least 2");
  expect_problem([] { make_series({}, {}); }, "/h", "at least 2");
}

TEST(ExtrapSeries, ReportsEveryProblemAtOnce) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    make_series({-1, 2, nan}, {1, nan, 3});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 3u) << e.what();
  }
}

TEST(ExtrapSeries, InverseHWeightsAreNormalised) {
  // W = (1, 1/2, 1/4), ΣW = 7/4 -> w = (4/7, 2/7, 1/7).
  const auto w = fit_weights({1, 2, 4}, Weighting::kInverseH);
  EXPECT_DOUBLE_EQ(w[0], 4.0 / 7);
  EXPECT_DOUBLE_EQ(w[1], 2.0 / 7);
  EXPECT_DOUBLE_EQ(w[2], 1.0 / 7);
  const auto u = fit_weights({1, 2, 4, 8}, Weighting::kUniform);
  for (double wi : u) EXPECT_DOUBLE_EQ(wi, 0.25);
}

TEST(ExtrapSeries, DataRangeAndConstancy) {
  EXPECT_DOUBLE_EQ(data_range({3, 1, 2, 5}), (5.0 - 1.0) / 3.0);
  EXPECT_TRUE(is_constant({7, 7, 7, 7}));
  EXPECT_TRUE(is_constant({0, 0, 0}));
  EXPECT_FALSE(is_constant({7, 7, 7.001, 7}));
}

TEST(ExtrapSeriesIo, ParsesJson) {
  const Series s = parse_series_json(R"({"h": [2, 1, 4, 3], "f": [20, 10, 40, 30], "name": "x"})", "s.json");
  EXPECT_EQ(s.h, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(s.f, (std::vector<double>{10, 20, 30, 40}));
}

TEST(ExtrapSeriesIo, JsonProblemsHavePointers) {
  expect_problem([] { parse_series_json(R"({"h": [1, "a"], "f": [1, 2]})", "s.json"); }, "/h/1", "number");
  expect_problem([] { parse_series_json(R"({"f": [1, 2]})", "s.json"); }, "/h", "missing");
  expect_problem([] { parse_series_json(R"({"h": [1, 2], "f": [1, NaN]})", "s.json"); }, "s.json:1:24", "invalid JSON");
  expect_problem([] { parse_series_json(R"([1, 2])", "s.json"); }, "s.json", "object");
}

TEST(ExtrapSeriesIo, ParsesCsvWithHeaderCommentsAndExtraColumns) {
  const std::string csv = "# my study\ncase,h,f\nA,0.5, 5\n\nA,1.0,10\nA,0.25,2.5\n";
  const Series s = parse_series_csv(csv, "s.csv");
  EXPECT_EQ(s.h, (std::vector<double>{0.25, 0.5, 1.0}));
  EXPECT_EQ(s.f, (std::vector<double>{2.5, 5, 10}));
}

TEST(ExtrapSeriesIo, CsvProblemsNameTheLine) {
  expect_problem([] { parse_series_csv("h,f\n1,2\n2,abc\n", "s.csv"); }, "s.csv:3", "not a number");
  expect_problem([] { parse_series_csv("h,f\n1,2\n2,nan\n", "s.csv"); }, "s.csv:3", "finite");
  expect_problem([] { parse_series_csv("x,y\n1,2\n", "s.csv"); }, "s.csv:1", "header");
  expect_problem([] { parse_series_csv("h,f\n1,2\n3,4\n1,5\n", "s.csv"); }, "s.csv:4", "duplicate");
  expect_problem([] { parse_series_csv("", "s.csv"); }, "s.csv", "empty");
}

// A file of kMaxSeriesPoints points is read; one more is refused naming the
// file and the limit (docs/LIMITS.md "gridfree extrapolate").
TEST(ExtrapSeriesIo, AFileOverThePointLimitIsRefusedNamingIt) {
  const auto dir = std::filesystem::temp_directory_path() / ("gridfree_series_limit_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](std::size_t n, const char* name) {
    std::ofstream out(dir / name);
    out << "h,f\n";
    for (std::size_t i = 0; i < n; ++i) out << 1.0 + static_cast<double>(i) * 1e-3 << ',' << 2.0 + 1e-6 * i << '\n';
    return dir / name;
  };
  EXPECT_EQ(read_series_file(write(kMaxSeriesPoints, "at.csv")).size(), kMaxSeriesPoints);
  const auto over = write(kMaxSeriesPoints + 1, "over.csv");
  expect_problem([&] { read_series_file(over); }, over.string(), "at most 10000");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace gridfree
