// SPDX-License-Identifier: GPL-3.0-or-later
// Report writing at ensemble scale: time, memory and page sizes of
// `write_study_report` for a synthetic study of S series × 18 grids, with
// the library extrapolator the orchestrator uses and no PDF/PNG export (the
// converter's child processes are measured apart).
//
//   report_scale --series 2700 [--out DIR] [--writes 2]
//
// The study: C cases × 6 drag laws × 3 filter widths (S rounded up to a
// multiple of 18), the paper's 18 grids, f = f0 + c h^1.6 with a per-series
// f0 and c and a deterministic ±0.02 % ripple, one grid in 50 diverged. One
// process per size: the peak RSS printed is this process's (getrusage).
// `--writes 2` writes the report a second time over the first, nothing
// changed (what the orchestrator does while series finish, its
// extrapolations remembered), and prints that write's time too.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "report/extrapolation_memo.h"
#include "report/report.h"
#include "report/series_coverage.h"

namespace {

constexpr double kGrids[] = {3.3,   2.762, 2.311, 1.934, 1.619, 1.355, 1.134, 0.949, 0.794,
                             0.665, 0.556, 0.466, 0.39,  0.326, 0.273, 0.228, 0.191, 0.16};
constexpr const char* kDrags[] = {"bvk", "gidaspow", "gidaspow_blend", "wen_yu", "hkl", "syamlal_obrien"};
constexpr double kFwhm[] = {3, 6, 12};

gridfree::StudyReportData synthetic(int series) {
  gridfree::StudyReportData d;
  d.study_name = "scale" + std::to_string(series);
  d.status = "done";
  d.version = "gridfree (report_scale)";
  d.baseline_description = "factorial";
  d.export_charts = false;
  const int cases = (series + 17) / 18;
  long long id = 0;
  int grid_count = 0;
  for (int c = 0; c < cases; ++c) {
    for (const char* drag : kDrags) {
      for (double fwhm : kFwhm) {
        gridfree::SeriesData s{++id, "inst" + std::to_string(c), "superbee", drag, "diffusion", fwhm, "done", {}, {}};
        const double f0 = 1000 + 3.0 * c + 7.0 * static_cast<double>(id % 6);
        const double k = 4 + static_cast<double>(id % 5);
        for (double h : kGrids) {
          gridfree::GridPoint g;
          g.job_hash = "h" + std::to_string(id) + "_" + std::to_string(h);
          g.delta_star = h;
          g.nx = static_cast<int>(std::lround(30 / h));
          g.ny = static_cast<int>(std::lround(200 / h));
          g.nz = static_cast<int>(std::lround(10 / h));
          g.iterations = 20 + static_cast<int>(10 / h);
          g.cpu_s = 2e-5 * g.nx * g.ny * g.nz * g.iterations;
          g.wall_s = g.cpu_s / 1.6;
          g.peak_rss_mb = 20 + 4e-4 * g.nx * g.ny * g.nz;
          if (++grid_count % 50 == 0) {
            g.status = "diverged";
            g.reason = "residual grew by 1e6";
          } else {
            g.status = "converged";
            g.dp_star = f0 + k * std::pow(h, 1.6) * (1 + 2e-4 * std::sin(7.0 * h + static_cast<double>(id)));
          }
          s.grids.push_back(std::move(g));
        }
        d.series.push_back(std::move(s));
      }
    }
  }
  return d;
}

std::uintmax_t folder_bytes(const std::filesystem::path& dir, std::uintmax_t& largest, int& files) {
  std::uintmax_t total = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    ++files;
    total += e.file_size();
    largest = std::max(largest, e.file_size());
  }
  return total;
}

// The coverage self-check of every series, as the orchestrator stores it
// when a series finishes (sched/series_finish.cpp), not timed: made for the
// first 54 series (about 0.3 s each) and copied to the others in turn (the
// same size and shape of data; a study of 2 700 would take 15 min here).
void store_coverage(gridfree::StudyReportData& d) {
  const auto extrapolate = gridfree::library_extrapolator({});
  constexpr std::size_t kMade = 54;
  for (std::size_t i = 0; i < d.series.size(); ++i) {
    auto& s = d.series[i];
    if (i >= kMade) {
      s.stored_coverage = d.series[i % kMade].stored_coverage;
      continue;
    }
    std::vector<double> h, f;
    for (const auto& g : s.grids) {
      if (!g.dp_star) continue;
      h.push_back(g.delta_star);
      f.push_back(*g.dp_star);
    }
    s.stored_coverage = gridfree::coverage_of(h, f, extrapolate(h, f), extrapolate);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"report writing at ensemble scale"};
  int series = 60, writes = 1;
  std::string out;
  app.add_option("--series", series, "series count (rounded up to a multiple of 18)")->check(CLI::PositiveNumber);
  app.add_option("--out", out, "report folder (default: a fresh temporary folder, removed)");
  app.add_option("--writes", writes, "report writes in a row (1 or 2)")->check(CLI::Range(1, 2));
  CLI11_PARSE(app, argc, argv);
  const bool keep = !out.empty();
  const std::filesystem::path dir =
      keep ? std::filesystem::path(out) : std::filesystem::temp_directory_path() / ("report_scale_" + std::to_string(series));
  std::filesystem::remove_all(dir);
  auto data = synthetic(series);
  store_coverage(data);
  double seconds[2] = {0, 0};
  // As the scheduler writes: the library extrapolator behind a memo kept
  // between writes (report/extrapolation_memo.h).
  gridfree::ExtrapolationMemo memo;
  const auto extrapolate = memo.wrap(gridfree::library_extrapolator({}));
  for (int w = 0; w < writes; ++w) {
    const auto t0 = std::chrono::steady_clock::now();
    gridfree::write_study_report(data, dir, extrapolate);
    memo.end_write();
    seconds[w] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::uintmax_t largest = 0;
  int files = 0;
  const auto total = folder_bytes(dir, largest, files);
  const auto html = std::filesystem::file_size(dir / "report.html");
  std::printf("%8s %8s %8s %10s %10s %10s %8s %10s\n", "series", "write_s", "rewrite_s", "html_MB", "largest_MB",
              "total_MB", "files", "peak_MB");
  std::printf("%8zu %8.2f %8.2f %10.2f %10.2f %10.1f %8d %10.1f\n", data.series.size(), seconds[0], seconds[1],
              static_cast<double>(html) / 1e6, static_cast<double>(largest) / 1e6, static_cast<double>(total) / 1e6,
              files, static_cast<double>(ru.ru_maxrss) / 1024.0);
  if (!keep) std::filesystem::remove_all(dir);
  return 0;
}
