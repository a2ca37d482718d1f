// SPDX-License-Identifier: GPL-3.0-or-later
// The report as a reader's browser shows it (docs/REPORTS.md "First
// screen"), in headless Chromium (skipped when none is installed): a copy of
// report.html with a checking script appended is opened at a given window
// size, the script measures the laid-out page and writes what it found into
// the DOM, and --dump-dom hands it back.
//   - At 1400 × 900 and at 390 × 844 the first screen holds f0 ± U₀ of every
//     series of a two-series study, exactly as series.csv's f0 and u0 print
//     (extrap/value_format.h), above the fold and (390 px) not cut off at
//     the right.
//   - In a 30-series study (summary layout) the filter `failed>0` shows
//     exactly the series with a failed grid, `drag:hkl` exactly the hkl
//     series, and the word `12` no series whose name merely contains 12.
//   - At 390 px every text of every SVG shown is at least 11 px high.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/value_format.h"
#include "report/report.h"
#include "test_files.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using test_support::slurp;

// n series of f = f0 + c·h^1.5 on six grids; every 4th (k = 0, 4, …) also
// has a grid that diverged. Drag alternates bvk/hkl, the case number runs
// PC1…PCn (so labels such as PC12 and PC1 exist together).
StudyReportData screen_study(int n) {
  StudyReportData d;
  d.study_name = "first-screen-check";
  d.status = "done";
  d.version = "gridfree test";
  for (int k = 0; k < n; ++k) {
    SeriesData s{k + 1, "PC" + std::to_string(k + 1), "superbee", k % 2 ? "hkl" : "bvk", "diffusion", 6, "done", {}, {}};
    for (double h : {3.0, 2.5, 2.0, 1.5, 1.0, 0.75}) {
      GridPoint g;
      g.delta_star = h;
      g.nx = g.ny = g.nz = static_cast<int>(std::lround(10 / h));
      g.status = "converged";
      g.dp_star = 1000.0 + 7.0 * k + (0.4 + 0.01 * k) * std::pow(h, 1.5) + 0.003 * std::sin(5.0 * h + k);
      g.cpu_s = 1000 / (h * h * h);
      g.wall_s = g.cpu_s / 2;
      s.grids.push_back(g);
    }
    if (k % 4 == 0) {
      GridPoint bad;
      bad.delta_star = 0.5;
      bad.status = "diverged";
      bad.reason = "residual grew";
      s.grids.push_back(bad);
    }
    d.series.push_back(s);
  }
  return d;
}

// Measures the laid-out page; the result goes into <pre id="gf-check">.
constexpr const char* kCheck = R"js(
<script>
(function () {
  var out = {width: window.innerWidth, height: window.innerHeight, answer: [], small: [], svgs: 0, texts: 0};
  document.querySelectorAll('#answer tbody tr').forEach(function (tr) {
    var td = tr.querySelectorAll('td'), b = td[1].getBoundingClientRect();
    out.answer.push({series: td[0].textContent, f0: td[1].textContent, bottom: b.bottom, right: b.right});
  });
  document.querySelectorAll('svg').forEach(function (svg) {
    var box = svg.getBoundingClientRect();
    if (box.width === 0 || box.height === 0) return;  // not shown at this width
    ++out.svgs;
    var vb = svg.viewBox.baseVal, scale = vb && vb.width ? box.width / vb.width : 1;
    svg.querySelectorAll('text, tspan').forEach(function (t) {
      if (!t.textContent.trim()) return;
      ++out.texts;
      var px = parseFloat(getComputedStyle(t).fontSize) * scale;
      if (px < 11) out.small.push(px.toFixed(2) + ' px: ' + t.textContent.slice(0, 40));
    });
  });
  var input = document.getElementById('series-filter');
  if (input) {
    out.filter = {};
    ['failed>0', 'drag:hkl', '12', 'pc12', 'verdict:no-such', 'nosuchfield:1'].forEach(function (q) {
      input.value = q;
      input.dispatchEvent(new Event('input'));
      out.filter[q] = [];
      document.querySelectorAll('#series-rows tbody tr').forEach(function (tr) {
        if (tr.style.display !== 'none') out.filter[q].push(tr.querySelector('td').textContent);
      });
    });
  }
  parent.postMessage(JSON.stringify(out), '*');
})();
</script>
)js";

std::string dom_unescape(std::string t) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}}) {
    for (auto at = t.find(from); at != std::string::npos; at = t.find(from, at + to.size())) t.replace(at, from.size(), to);
  }
  return t;
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// The page opened at width × height with the checking script; its findings.
// Headless Chromium's window is at least 500 px wide, so the page is opened
// in an iframe of the size asked for (its media queries see that width),
// which posts its findings to the harness page that --dump-dom returns.
nlohmann::json measure(const fs::path& report_html, int width, int height) {
  const fs::path dir = report_html.parent_path();
  const fs::path page = dir / "check.html", harness = dir / "harness.html", dom = dir / "dom.html",
                 profile = dir / "chromium-profile";
  std::string html = slurp(report_html);
  html.insert(html.rfind("</body>"), kCheck);
  std::ofstream(page) << html;
  std::ofstream(harness) << "<!DOCTYPE html><html><body style=\"margin:0\"><iframe src=\"check.html\" style=\"border:0;"
                            "width:" << width << "px;height:" << height << "px\"></iframe><pre id=\"gf-check\"></pre>"
                            "<script>window.addEventListener('message', function (e) {"
                            " document.getElementById('gf-check').textContent = e.data; });</script></body></html>";
  fs::remove_all(profile);
  const std::string cmd = "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --hide-scrollbars --virtual-time-budget=10000 --window-size=" +
                          std::to_string(std::max(width, 1400)) + "," + std::to_string(height + 100) +
                          " --user-data-dir='" + profile.string() + "' --dump-dom 'file://" +
                          fs::absolute(harness).string() + "' > '" + dom.string() + "' 2>/dev/null";
  if (std::system(cmd.c_str()) != 0) return {};
  const std::string text = slurp(dom);
  const auto open = text.find("<pre id=\"gf-check\">");
  if (open == std::string::npos) return {};
  const auto begin = text.find('>', open) + 1;
  return nlohmann::json::parse(dom_unescape(text.substr(begin, text.find("</pre>", begin) - begin)), nullptr, false);
}

// series.csv's rows as maps from column name to text.
std::vector<std::map<std::string, std::string>> series_csv(const fs::path& dir) {
  std::ifstream in(dir / "series.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    // The columns read here (series, f0, u0, failed, drag) hold no commas or quotes.
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char ch : line) {
      if (ch == '"') quoted = !quoted;
      else if (ch == ',' && !quoted) cells.push_back(std::exchange(cell, {}));
      else cell += ch;
    }
    cells.push_back(cell);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) row[names[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

class ReportFirstScreen : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_chromium()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
    dir_ = fs::path(::testing::TempDir()) / ("gridfree-first-screen-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ReportFirstScreen, HoldsF0AndUOfEverySeriesAtDesktopAndPhoneWidths) {
  const ReportFiles files = write_study_report(screen_study(2), dir_);
  const auto rows = series_csv(dir_);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1400, 900}, {390, 844}}) {
    const nlohmann::json m = measure(files.html, w, h);
    ASSERT_TRUE(m.is_object()) << w;
    EXPECT_EQ(m["width"], w);
    ASSERT_EQ(m["answer"].size(), rows.size()) << w;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& a = m["answer"][i];
      const double f0 = std::stod(rows[i].at("f0")), u0 = std::stod(rows[i].at("u0"));
      EXPECT_EQ(a["series"], rows[i].at("series"));
      EXPECT_EQ(a["f0"], format_value_u(f0, u0)) << w;
      EXPECT_LE(a["bottom"].get<double>(), h) << "f0 ± U of " << rows[i].at("series") << " below the fold at " << w;
      EXPECT_LE(a["right"].get<double>(), w) << "f0 ± U of " << rows[i].at("series") << " cut off at " << w;
    }
    if (w == 390) {
      EXPECT_GT(m["texts"].get<int>(), 50);
      EXPECT_TRUE(m["small"].empty()) << m["small"].dump(1);
    }
  }
}

TEST_F(ReportFirstScreen, FilterFindsExactlyTheSeriesAskedForAndSvgTextIsLegibleOnAPhone) {
  const ReportFiles files = write_study_report(screen_study(30), dir_);  // beyond 24: the summary layout
  const auto rows = series_csv(dir_);
  ASSERT_EQ(rows.size(), 30u);
  std::set<std::string> failed, hkl;
  for (const auto& r : rows) {
    if (std::stoi(r.at("failed")) > 0) failed.insert(r.at("series"));
    if (r.at("drag") == "hkl") hkl.insert(r.at("series"));
  }
  ASSERT_EQ(failed.size(), 8u);  // k = 0, 4, …, 28
  const nlohmann::json m = measure(files.html, 390, 844);
  ASSERT_TRUE(m.is_object());
  ASSERT_TRUE(m.contains("filter"));
  const auto shown = [&](const char* q) {
    std::set<std::string> out;
    for (const auto& s : m["filter"][q]) out.insert(s.get<std::string>());
    return out;
  };
  EXPECT_EQ(shown("failed>0"), failed);
  EXPECT_EQ(shown("drag:hkl"), hkl);
  EXPECT_TRUE(shown("12").empty());  // no word "12": PC12, PC1 do not match
  EXPECT_EQ(shown("pc12").size(), 1u);
  EXPECT_TRUE(shown("verdict:no-such").empty());
  EXPECT_TRUE(shown("nosuchfield:1").empty());
  EXPECT_GT(m["svgs"].get<int>(), 2);
  EXPECT_TRUE(m["small"].empty()) << m["small"].dump(1);
}

}  // namespace
}  // namespace gridfree
