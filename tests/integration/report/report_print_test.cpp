// SPDX-License-Identifier: GPL-3.0-or-later
// The report of a quickstart-like study run with the fake worker, printed
// to A4 PDF by headless Chromium: every number of every table cell of
// report.html appears whole in the PDF's text (pdftotext -layout), so none
// is split across lines; and every chart text lies inside its SVG's box,
// no two overlapping.
// Skipped when chromium or pdftotext is not installed (`make test`
// installs both).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "svg_text_boxes.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::shell_quote;

// Quickstart's PC1 as two cases that the fake worker solves like the
// demo's bursting bubble (DP* = 1017 + K − 2.3 Δ*^1.6 + 0.05 sin 7Δ*, K = 0
// and 2: numbers with many digits), two schemes × two drag laws, on the
// demo's five grids.
fs::path write_print_study(const fs::path& dir) {
  auto doc = gridfree::test_support::quickstart_document();
  doc["name"] = "print";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"bubble", pc1}, {"bubbleplus2", pc1}};
  doc["factors"] = {{"convection", {"superbee", "fou"}}, {"fwhm_dp", {6}}, {"drag", {"bvk", "hkl"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {2.0, 1.5, 1.0, 0.786, 0.667}}};
  const auto file = dir / "print.json";
  std::ofstream(file) << doc.dump(2);
  return file;
}

bool print_tool_installed(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

std::string html_text_of(std::string t) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}}) {
    for (auto at = t.find(from); at != std::string::npos; at = t.find(from, at + to.size())) t.replace(at, from.size(), to);
  }
  return t;
}

// Numbers as they are written: digits with decimal points and an exponent
// ("1016.995", "3.51e-08", "0.786"); a number split across two lines of the
// PDF becomes two shorter numbers there.
const std::regex kNumber("[0-9]+(?:\\.[0-9]+)*(?:e[-+][0-9]+)?");

std::map<std::string, int> number_counts(const std::string& text) {
  std::map<std::string, int> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kNumber); it != std::sregex_iterator(); ++it)
    ++out[it->str()];
  return out;
}

TEST(ReportPrint, EveryTableNumberIsWholeInThePdf) {
  if (!print_tool_installed("chromium")) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  if (!print_tool_installed("pdftotext")) GTEST_SKIP() << "pdftotext is not installed (apt-get install poppler-utils)";
  const auto dir = gridfree::test_support::fresh_scratch_dir("report_print", "quickstart");
  const auto study = write_print_study(dir);
  const auto run = gridfree::test_support::gridfree_in(
      dir, "run " + shell_quote(study.string()) + " -j 2 --db g.sqlite --out " + shell_quote((dir / "out").string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path html_file = dir / "out" / "report.html", pdf = dir / "report.pdf", txt = dir / "report.txt";
  ASSERT_TRUE(fs::exists(html_file));
  const std::string print = "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                            " --disable-background-networking --disable-component-update --disable-sync"
                            " --window-size=1400,1000 --no-pdf-header-footer --user-data-dir=" +
                            shell_quote((dir / "profile").string()) + " --print-to-pdf=" + shell_quote(pdf.string()) +
                            " " + shell_quote("file://" + fs::absolute(html_file).string()) +
                            " >/dev/null 2>&1 && pdftotext -layout " + shell_quote(pdf.string()) + " " +
                            shell_quote(txt.string());
  ASSERT_EQ(std::system(print.c_str()), 0) << print;
  const std::string html = gridfree::test_support::slurp(html_file);
  const auto in_pdf = number_counts(gridfree::test_support::slurp(txt));
  // Every number of every table cell, as often as the cells hold it (the
  // PDF may hold it more often: the same number in a chart or a verdict).
  std::map<std::string, int> in_cells;
  // Cells of screen-only columns (fit details series.csv keeps) are not printed.
  const std::regex cell("<td([^>]*)>([^<]*)</td>");
  int cells = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator(); ++it, ++cells) {
    if ((*it)[1].str().find("screen-only") != std::string::npos) continue;
    for (const auto& [number, n] : number_counts(html_text_of((*it)[2]))) in_cells[number] += n;
  }
  EXPECT_GT(cells, 200);  // 8 series: series, differences, cost, gci and grids tables
  EXPECT_GT(in_cells.size(), 50u);
  for (const auto& [number, n] : in_cells) {
    const auto found = in_pdf.find(number);
    EXPECT_GE(found == in_pdf.end() ? 0 : found->second, n) << "table number not whole in the PDF: " << number;
  }
  // Every chart's text inside its SVG's box and apart from the others
  // (estimated, svg_text_boxes.h).
  int svgs = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out")) {
    if (entry.path().extension() != ".svg") continue;
    ++svgs;
    for (const auto& outside : gridfree::test::texts_outside_view_box(gridfree::test_support::slurp(entry.path())))
      ADD_FAILURE() << entry.path().filename() << ": text outside the SVG: " << outside;
    for (const auto& overlap : gridfree::test::overlapping_texts(gridfree::test_support::slurp(entry.path())))
      ADD_FAILURE() << entry.path().filename() << ": " << overlap;
  }
  EXPECT_GE(svgs, 8);
  // Every table of these 8 series fits a portrait page once the series
  // table's fit details stay on screen: no landscape page (pdfinfo, when
  // poppler-utils has it).
  if (print_tool_installed("pdfinfo")) {
    const fs::path sizes = dir / "sizes.txt";
    ASSERT_EQ(std::system(("pdfinfo -f 1 -l 999 " + shell_quote(pdf.string()) + " > " + shell_quote(sizes.string()))
                              .c_str()),
              0);
    const std::string info = gridfree::test_support::slurp(sizes);
    const std::regex page_size("Page +([0-9]+) size: +([0-9.]+) x ([0-9.]+)");
    int pages = 0;
    for (auto it = std::sregex_iterator(info.begin(), info.end(), page_size); it != std::sregex_iterator(); ++it, ++pages)
      EXPECT_LT(std::stod((*it)[2]), std::stod((*it)[3])) << "landscape page " << (*it)[1];
    EXPECT_GT(pages, 2);
  }
}

}  // namespace
