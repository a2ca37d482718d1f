// SPDX-License-Identifier: GPL-3.0-or-later
// Integration of the report with the real extrapolation library, and a
// rendering check of report.html in headless Chromium (skipped when no
// Chromium is installed: `make test` installs it).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/report.h"
#include "test_files.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

using test_support::slurp;

int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// Two series of exact first-order data f = f0 + c·h on six grids (the power
// law f0 + c h^p with p = 1 and the mixed fit both reproduce it exactly),
// differing only in the drag law; the second also has a failed grid.
StudyReportData first_order_study() {
  StudyReportData d;
  d.study_name = "render-check";
  d.status = "done";
  d.version = "gridfree test";
  const double f0[2] = {1158.8, 850.0}, c[2] = {0.6, 1.5};
  const char* drag[2] = {"bvk", "hkl"};
  for (int s = 0; s < 2; ++s) {
    SeriesData series{s + 1, "PC1", "superbee", drag[s], "diffusion", 6, "done", {}, {}};
    for (double h : {3.0, 2.5, 2.0, 1.5, 1.0, 0.75}) {
      GridPoint g;
      g.delta_star = h;
      g.nx = g.ny = g.nz = static_cast<int>(std::lround(10 / h));
      g.status = "converged";
      g.dp_star = f0[s] + c[s] * h;
      g.cpu_s = 1000 / (h * h * h);
      g.wall_s = g.cpu_s / 2;
      series.grids.push_back(g);
    }
    if (s == 1) {
      GridPoint bad;
      bad.delta_star = 0.5;
      bad.status = "failed";
      bad.reason = "worker crashed";
      series.grids.push_back(bad);
    }
    d.series.push_back(series);
  }
  return d;
}

class ReportRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("gridfree-render-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    files_ = write_study_report(first_order_study(), dir_);  // the extrapolation library
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  ReportFiles files_;
};

TEST_F(ReportRender, LibraryExtrapolationRecoversF0) {
  const std::string csv = slurp(dir_ / "series.csv");
  // The f0 column of each data row. Exact first-order data: the fits
  // reproduce f0 up to the least-squares round-off and the p search
  // resolution of the library; 1e-6 relative is far below any plotted scale.
  std::istringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  std::vector<std::string> names;
  for (std::istringstream h(header); std::getline(h, line, ',');) names.push_back(line);
  const auto f0_col = std::find(names.begin(), names.end(), "f0") - names.begin();
  const double expected[2] = {1158.8, 850.0};
  for (int s = 0; s < 2; ++s) {
    ASSERT_TRUE(std::getline(lines, line));
    std::vector<std::string> cells;
    for (std::istringstream r(line); std::getline(r, header, ',');) cells.push_back(header);
    ASSERT_GT(cells.size(), static_cast<std::size_t>(f0_col));
    EXPECT_NEAR(std::stod(cells[f0_col]), expected[s], 1e-6 * expected[s]) << line;
  }
  // One-factor difference (drag): 2|1158.8 − 850|/(1158.8 + 850).
  std::istringstream diff(slurp(dir_ / "differences.csv"));
  const double d = 2 * (1158.8 - 850.0) / (1158.8 + 850.0);
  std::string diff_header, diff_row;
  ASSERT_TRUE(std::getline(diff, diff_header));
  ASSERT_TRUE(std::getline(diff, diff_row));
  std::vector<std::string> diff_names, diff_cells;
  for (std::istringstream h(diff_header); std::getline(h, line, ',');) diff_names.push_back(line);
  for (std::istringstream r(diff_row); std::getline(r, line, ',');) diff_cells.push_back(line);
  const auto d_col = std::find(diff_names.begin(), diff_names.end(), "relative_difference") - diff_names.begin();
  ASSERT_GT(diff_cells.size(), static_cast<std::size_t>(d_col));
  EXPECT_NEAR(std::stod(diff_cells[d_col]), d, 1e-6);
  EXPECT_NE(slurp(dir_ / "failures.csv").find("worker crashed"), std::string::npos);
}

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string cmd = std::string("command -v ") + name + " >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return name;
  }
  return {};
}

TEST_F(ReportRender, ChromiumRendersTheSvgCharts) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  const fs::path profile = dir_ / "chromium-profile";
  const fs::path dom = dir_ / "dom.html";
  const std::string cmd = "timeout 120 " + chromium +
                          " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --user-data-dir='" + profile.string() + "' --dump-dom 'file://" +
                          fs::absolute(files_.html).string() + "' > '" + dom.string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::string text = slurp(dom);
  // The parsed DOM holds every inline chart as an svg element, with its
  // drawn content, and the page title.
  // Each chart twice (wide and narrow, html_blocks.h figure) + the stability map (not a chart).
  EXPECT_EQ(count_of(text, "<svg"), 2 * static_cast<int>(files_.svg.size()) + 1);
  EXPECT_GE(count_of(text, "<circle"), 12);  // 6 + 6 converged grids in the Fig. 1 charts
  EXPECT_NE(text.find("<title>Grid-convergence report: render-check</title>"), std::string::npos);
  EXPECT_NE(text.find("What a target costs"), std::string::npos);
}

// Minimal RFC 4180 reader: rows of fields ("" quoting, quoted commas/newlines).
std::vector<std::vector<std::string>> read_csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (quoted) {
      if (ch == '"' && i + 1 < text.size() && text[i + 1] == '"') field += text[++i];
      else if (ch == '"') quoted = false;
      else field += ch;
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      rows.back().push_back(field);
      field.clear();
    } else if (ch == '\n') {
      rows.back().push_back(field);
      field.clear();
      rows.emplace_back();
    } else if (ch != '\r') {
      field += ch;
    }
  }
  if (!field.empty() || !rows.back().empty()) rows.back().push_back(field);
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

std::string without_space(const std::string& text) {
  std::string out;
  for (char ch : text)
    if (!std::isspace(static_cast<unsigned char>(ch))) out += ch;
  return out;
}

std::string html_unescape(std::string t) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}}) {
    for (auto at = t.find(from); at != std::string::npos; at = t.find(from, at + to.size())) t.replace(at, from.size(), to);
  }
  return t;
}

// Printed to A4 from a 1400 px window, the report loses no column: every
// table header of report.html and every series' verdict reasons are in the
// PDF's text (pdftotext). A table wider than the page would be cut at the
// page edge and its last headers would be missing from the text.
TEST_F(ReportRender, ChromiumPrintsEveryColumnAndNoteToA4) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  if (std::system("command -v pdftotext >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdftotext is not installed (apt-get install poppler-utils)";
  const fs::path profile = dir_ / "chromium-profile";
  const fs::path pdf = dir_ / "report.pdf", txt = dir_ / "report.txt";
  const std::string cmd = "timeout 120 " + chromium +
                          " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --window-size=1400,1000 --no-pdf-header-footer --user-data-dir='" + profile.string() +
                          "' --print-to-pdf='" + pdf.string() + "' 'file://" + fs::absolute(files_.html).string() +
                          "' >/dev/null 2>&1 && pdftotext '" + pdf.string() + "' '" + txt.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::string text = without_space(slurp(txt));
  const std::string html = slurp(files_.html);
  int headers = 0;
  for (auto at = html.find("<th>"); at != std::string::npos; at = html.find("<th>", at + 1)) {
    const auto end = html.find("</th>", at);
    const std::string header = without_space(html_unescape(html.substr(at + 4, end - at - 4)));
    ++headers;
    EXPECT_NE(text.find(header), std::string::npos) << "column header missing from the PDF: " << header;
  }
  EXPECT_GT(headers, 40);  // series, differences, cost, gci, failures and grids tables
  // The "what a target costs" table, by name: target → cheapest grid → its cost.
  for (const char* header : {"targetRDE", "cheapestΔ*", "cells×iterations", "CPUs", "peakMB", "itsRDE"})
    EXPECT_NE(text.find(header), std::string::npos) << "cost-table column missing from the PDF: " << header;
  const auto rows = read_csv_rows(slurp(dir_ / "series.csv"));
  ASSERT_EQ(rows.size(), 3u);
  const auto col = std::find(rows[0].begin(), rows[0].end(), "verdict_reasons") - rows[0].begin();
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_GT(rows[r].size(), static_cast<std::size_t>(col));
    std::istringstream reasons(rows[r][col]);
    for (std::string reason; std::getline(reasons, reason, ';');)
      EXPECT_NE(text.find(without_space(reason)), std::string::npos) << "note missing from the PDF: " << reason;
  }
}


// An ensemble of three instances (f0 offsets 0, 2, 7) under two drag laws:
// the Ensembles section's budget chart is drawn by Chromium with its
// curves, and its tables are in the DOM.
TEST(ReportRenderEnsembles, ChromiumRendersTheBudgetChart) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  StudyReportData d = first_order_study();
  d.study_name = "render-ensemble";
  d.series.clear();
  long long id = 0;
  for (const char* drag : {"bvk", "hkl"}) {
    for (int k : {0, 2, 7}) {
      SeriesData series{++id, "t" + std::to_string(k), "superbee", drag, "diffusion", 6, "done", {}, {}};
      for (double h : {3.0, 2.5, 2.0, 1.5, 1.0, 0.75}) {
        GridPoint g;
        g.delta_star = h;
        g.nx = g.ny = g.nz = static_cast<int>(std::lround(10 / h));
        g.status = "converged";
        g.dp_star = (drag[0] == 'b' ? 1000.0 : 1300.0) + k + 0.8 * h + 0.05 * h * h;
        series.grids.push_back(g);
      }
      d.series.push_back(series);
    }
  }
  d.ensembles = {{"snap", {"t0", "t2", "t7"}}};
  const fs::path dir = fs::path(::testing::TempDir()) / ("gridfree-render-ens-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const ReportFiles files = write_study_report(d, dir);
  ASSERT_TRUE(fs::exists(dir / "budget_snap.svg"));
  const fs::path dom = dir / "dom.html";
  const std::string cmd = "timeout 120 " + chromium +
                          " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --user-data-dir='" + (dir / "profile").string() + "' --dump-dom 'file://" +
                          fs::absolute(files.html).string() + "' > '" + dom.string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::string text = slurp(dom);
  // Each chart twice (wide and narrow) + the stability map (not a chart).
  EXPECT_EQ(count_of(text, "<svg"), 2 * static_cast<int>(files.svg.size()) + 1);
  EXPECT_NE(text.find("Ensembles and uncertainty budget"), std::string::npos);
  EXPECT_NE(text.find("Uncertainty budget, ensemble snap"), std::string::npos);
  EXPECT_NE(text.find("instance spread s/|mean|"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gridfree
