// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end test of write_study_report on the synthetic study of
// report_test_data.h: every file is written, the tables hold the numbers
// computed here from the manufactured data, the HTML is self-contained and
// well formed, and failed / insufficient / incomplete series are flagged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

#include "report/chart_export.h"
#include "report/report.h"
#include "report_test_data.h"
#include "test_files.h"
#include "xml_check.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using Row = std::map<std::string, std::string>;

using test_support::slurp;

// RFC 4180 reader, enough for the report's CSV (quoted fields, "" escapes).
std::vector<Row> read_csv(const fs::path& p) {
  const std::string text = slurp(p);
  std::vector<std::vector<std::string>> records(1);
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (quoted) {
      if (ch == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        field += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      records.back().push_back(field);
      field.clear();
    } else if (ch == '\n') {
      records.back().push_back(field);
      field.clear();
      records.emplace_back();
    } else {
      field += ch;
    }
  }
  records.pop_back();  // after the final newline
  std::vector<Row> rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    EXPECT_EQ(records[r].size(), records[0].size()) << p << " record " << r;
    Row row;
    for (std::size_t c = 0; c < records[0].size() && c < records[r].size(); ++c) row[records[0][c]] = records[r][c];
    rows.push_back(row);
  }
  return rows;
}

const Row& find_row(const std::vector<Row>& rows, const std::string& series, double h) {
  for (const Row& r : rows) {
    if (r.at("series") == series && std::abs(std::stod(r.at("delta_star")) - h) < 1e-12) return r;
  }
  static const Row none;
  ADD_FAILURE() << "no row for " << series << " at " << h;
  return none;
}

class ReportWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("gridfree-report-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    files_ = write_study_report(test::synthetic_study(), dir_, test::fake_extrapolation);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  ReportFiles files_;
};

TEST_F(ReportWriter, WritesEveryFileAndNoTemporaries) {
  for (const char* name : {"report.md", "report.html", "grids.csv", "series.csv", "differences.csv", "gci.csv",
                           "cost.csv", "failures.csv", "coverage.csv", "verdict_counts.csv", "stability.csv",
                           "stability_series.csv", "stability_map.svg", "fig2_rde.svg", "speed_accuracy.svg",
                           "speed_accuracy_work.svg",
                           "fig1_01_PC1_superbee_fwhm6_bvk.svg", "gci_01_PC1_superbee_fwhm6_bvk.svg",
                           "fig1_02_PC1_superbee_fwhm6_hkl.svg", "fig1_03_PC2_superbee_fwhm6_bvk.svg",
                           "gci_03_PC2_superbee_fwhm6_bvk.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << name;
  }
  EXPECT_EQ(files_.html, dir_ / "report.html");
  EXPECT_EQ(files_.csv.size(), 10u);
  // PDF and PNG beside every SVG when rsvg-convert is installed (install-deps.sh).
  if (!find_svg_converter().empty()) {
    for (const auto& svg : files_.svg) {
      for (const char* ext : {".pdf", ".png"}) {
        auto copy = svg;
        copy.replace_extension(ext);
        EXPECT_TRUE(fs::is_regular_file(copy)) << copy;
        EXPECT_GT(fs::file_size(copy), 100u) << copy;
      }
    }
    EXPECT_NE(slurp(dir_ / "report.html").find("fig2_rde.pdf"), std::string::npos);
  }
  EXPECT_EQ(files_.svg.size(), 3u + 3u + 3u);  // overview (RDE, 2 × cost) + per-series fig1 + gci
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_NE(entry.path().filename().string().front(), '.') << "left over: " << entry.path();
  }
}

TEST_F(ReportWriter, GridsTableHoldsUncertainties) {
  const auto rows = read_csv(dir_ / "grids.csv");
  ASSERT_EQ(rows.size(), 4u + 5u + 4u);
  // A at Δ* = 2: f = 1000 + 8·2 = 1016, U = 1.25·16 + 0.5 = 20.5, RDE = 0.0205.
  const Row& a2 = find_row(rows, "PC1 superbee fwhm6 bvk", 2.0);
  EXPECT_DOUBLE_EQ(std::stod(a2.at("dp_star")), 1016.0);
  EXPECT_DOUBLE_EQ(std::stod(a2.at("u")), 20.5);
  EXPECT_DOUBLE_EQ(std::stod(a2.at("rde")), 0.0205);
  EXPECT_DOUBLE_EQ(std::stod(a2.at("error_vs_f0")), 0.016);
  EXPECT_EQ(a2.at("cells"), std::to_string(15 * 100 * 5));
  EXPECT_EQ(a2.at("status"), "converged");
  // B at Δ* = 1.5: f = 1500 + 10·2.25 = 1522.5, U = 1.25·22.5 + 0.5 = 28.625.
  const Row& b15 = find_row(rows, "PC1 superbee fwhm6 hkl", 1.5);
  EXPECT_DOUBLE_EQ(std::stod(b15.at("u")), 28.625);
  // The diverged grid keeps its reason (a comma inside: quoted in the CSV).
  const Row& bad = find_row(rows, "PC1 superbee fwhm6 hkl", 0.25);
  EXPECT_EQ(bad.at("status"), "diverged");
  EXPECT_EQ(bad.at("dp_star"), "");
  EXPECT_EQ(bad.at("reason"), "residual grew by 1e6, diverged at iteration 12");
  // C has 3 converged grids: no uncertainty; its queued grid is listed too.
  const Row& c1 = find_row(rows, "PC2 superbee fwhm6 bvk", 1.0);
  EXPECT_EQ(c1.at("u"), "");
  EXPECT_EQ(find_row(rows, "PC2 superbee fwhm6 bvk", 0.5).at("status"), "queued");
}

TEST_F(ReportWriter, SeriesAndDifferencesTables) {
  const auto series = read_csv(dir_ / "series.csv");
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].at("f0"), "1000");
  EXPECT_EQ(series[1].at("f0"), "1500");
  EXPECT_EQ(series[1].at("ng"), "4");
  EXPECT_EQ(series[1].at("failed"), "1");
  // B: R_f = (1540 − 1502.5)/3 = 12.5; σ_RE/R_f = 0.04.
  EXPECT_DOUBLE_EQ(std::stod(series[1].at("data_range")), 12.5);
  EXPECT_DOUBLE_EQ(std::stod(series[1].at("sigma_re_over_rf")), 0.04);
  EXPECT_EQ(series[2].at("f0"), "");
  EXPECT_NE(series[2].at("note").find("insufficient grids"), std::string::npos);
  EXPECT_NE(series[2].at("note").find("incomplete"), std::string::npos);

  const auto diff = read_csv(dir_ / "differences.csv");
  ASSERT_EQ(diff.size(), 2u);
  EXPECT_EQ(diff[0].at("factor"), "drag");
  EXPECT_DOUBLE_EQ(std::stod(diff[0].at("relative_difference")), 2.0 * 500.0 / 2500.0);
  EXPECT_EQ(diff[1].at("factor"), "case");
  EXPECT_EQ(diff[1].at("relative_difference"), "");

  const auto failures = read_csv(dir_ / "failures.csv");
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].at("status"), "diverged");
  EXPECT_EQ(read_csv(dir_ / "gci.csv").size(), 5u);
}

TEST_F(ReportWriter, HtmlIsSelfContainedAndWellFormed) {
  const std::string html = slurp(dir_ / "report.html");
  EXPECT_EQ(test::xml_problem(html, true), "");
  for (const char* external : {"src=\"http", "href=\"http", "<link", "<script", "@import", "url(http"}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
  // Every chart inline twice (wide and narrow), and the stability map (stability_map.svg, not a chart).
  EXPECT_EQ(test::count_of(html, "<svg"), 2 * static_cast<int>(files_.svg.size()) + 1);
  EXPECT_NE(html.find("<title>Grid-convergence report: synthetic &lt;study&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("insufficient grids (3 solved, 4 needed)"), std::string::npos);
  EXPECT_NE(html.find("(incomplete)"), std::string::npos);
  EXPECT_NE(html.find("residual grew by 1e6"), std::string::npos);
}

TEST_F(ReportWriter, SvgFilesAreWellFormed) {
  for (const auto& svg : files_.svg) {
    EXPECT_EQ(test::xml_problem(slurp(svg)), "") << svg;
  }
  // The failed grid of B is drawn (× marker) in its Fig. 1 chart.
  const std::string b = slurp(dir_ / "fig1_02_PC1_superbee_fwhm6_hkl.svg");
  EXPECT_NE(b.find("failed / not converged"), std::string::npos);
  // The running series C shows its pending grid.
  EXPECT_NE(slurp(dir_ / "fig1_03_PC2_superbee_fwhm6_bvk.svg").find("pending"), std::string::npos);
}

TEST_F(ReportWriter, MarkdownLinksEveryChartAndTable) {
  const std::string md = slurp(dir_ / "report.md");
  for (const auto& svg : files_.svg) {
    EXPECT_NE(md.find("](" + svg.filename().string() + ")"), std::string::npos) << svg;
  }
  for (const auto& csv : files_.csv) {
    EXPECT_NE(md.find("](" + csv.filename().string() + ")"), std::string::npos) << csv;
  }
  EXPECT_NE(md.find("| PC1 superbee fwhm6 bvk |"), std::string::npos);
  EXPECT_NE(md.find("40.0%"), std::string::npos);  // the drag difference, in percent to 3 digits
}

TEST_F(ReportWriter, StaleSeriesChartsAreRemovedOtherFilesKept) {
  std::ofstream(dir_ / "fig1_99_gone.svg") << "<svg/>";
  std::ofstream(dir_ / "my_notes.txt") << "keep";
  write_study_report(test::synthetic_study(), dir_, test::fake_extrapolation);
  EXPECT_FALSE(fs::exists(dir_ / "fig1_99_gone.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "my_notes.txt"));
  EXPECT_TRUE(fs::exists(dir_ / "fig1_01_PC1_superbee_fwhm6_bvk.svg"));
}

TEST_F(ReportWriter, RewritingGivesTheSameBytes) {
  const std::string before = slurp(dir_ / "report.html");
  write_study_report(test::synthetic_study(), dir_, test::fake_extrapolation);
  EXPECT_EQ(slurp(dir_ / "report.html"), before);
}

}  // namespace
}  // namespace gridfree
