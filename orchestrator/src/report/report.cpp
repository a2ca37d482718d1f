// SPDX-License-Identifier: GPL-3.0-or-later
// write_study_report: builds the report content and writes every file.
//
// Order: CSV tables, SVG charts, then report.md and report.html last, so a
// reader who sees the new documents also finds the files they link to.
#include "report/report.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <spdlog/spdlog.h>

#include "report/atomic_file.h"
#include "report/chart_export.h"
#include "report/report_content.h"
#include "report/report_ensembles.h"
#include "report/report_tables.h"
#include "report/series_page.h"
#include "report/series_vocabulary.h"
#include "report/stability_section.h"

namespace gridfree {

namespace {

// Per-series charts of an earlier run whose series no longer exist (e.g. a
// study redefined under the same name) would be misleading: remove them; so
// would speed-accuracy charts once no series is converged (report_charts.cpp)
// and the RDE charts of the other layout (report_layout.h).
void remove_stale_charts(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& written) {
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool per_series = name.rfind("fig1_", 0) == 0 || name.rfind("gci_", 0) == 0 ||
                            name.rfind("speed_accuracy", 0) == 0 || name.rfind("fig2_rde", 0) == 0;
    const auto ext = entry.path().extension();
    if (!per_series || (ext != ".svg" && ext != ".pdf" && ext != ".png")) continue;
    auto as_svg = entry.path();
    as_svg.replace_extension(".svg");
    if (std::find(written.begin(), written.end(), as_svg) == written.end()) stale.push_back(entry.path());
  }
  for (const auto& path : stale) std::filesystem::remove(path, ec);
}

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `text` unless the file already holds it; true when written.
bool write_if_changed(const std::filesystem::path& file, const std::string& text) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && size == text.size() && read_file(file) == text) return false;
  write_file_atomically(file, text);
  return true;
}

// Summary layout (report_layout.h): series/<slug>.html and its charts, one
// series at a time (memory stays that of one series), each file written
// only when its bytes changed; files of series no longer in the study are
// removed. Per-series charts get no PDF/PNG copies here: thousands of
// conversions would take longer than the study's jobs.
void write_series_pages(const ReportContent& content, const std::filesystem::path& out_dir, ReportFiles& files,
                        const std::function<void()>& check_stop) {
  const auto dir = out_dir / "series";
  std::filesystem::create_directories(dir);
  remove_stale_temporaries(dir);
  const SeriesRowIndex rows = series_row_index(content);
  std::set<std::string> current;
  int rewritten = 0;
  for (std::size_t i = 0; i < content.series.size(); ++i) {
    check_stop();
    const auto charts = series_charts(content.series, i);
    std::vector<std::string> svgs;  // rendered once: the file and the page's inline copy
    for (const auto& c : charts) {
      svgs.push_back(render_svg(c.chart));
      current.insert(c.file);
      if (write_if_changed(dir / c.file, kSvgDeclaration + svgs.back())) ++rewritten;
      files.svg.push_back(dir / c.file);
    }
    const auto page = std::filesystem::path(series_page_file(content, i)).filename();
    current.insert(page.string());
    if (write_if_changed(dir / page, render_series_page(content, rows, i, charts, svgs))) ++rewritten;
  }
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    // A temporary (".<file>.tmp-<pid>-<n>") may be another writer's in flight:
    // those of killed writers went with remove_stale_temporaries above.
    if (!name.starts_with('.') && !current.count(name)) stale.push_back(entry.path());
  }
  for (const auto& path : stale) std::filesystem::remove(path, ec);
  spdlog::debug("report: {} series pages, {} files rewritten, {} stale removed", content.series.size(), rewritten,
                stale.size());
}

}  // namespace

ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir,
                               const StopRequested& stop) {
  return write_study_report(data, out_dir,
                            library_extrapolator({data.extrapolation_method, data.p_low, data.p_high, "inverse_h",
                                                  data.expected_order, study_vocabulary(data.series).h_symbol}),
                            stop);
}

ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir,
                               const Extrapolator& extrapolate, const StopRequested& stop) {
  const std::function<void()> check_stop = [&stop] {
    if (stop && stop()) throw ReportInterrupted();
  };
  std::filesystem::create_directories(out_dir);
  remove_stale_temporaries(out_dir);  // once per write: one listing of the folder
  ReportContent content = build_report_content(data, extrapolate);
  ReportFiles files;
  for (const NamedTable* t : {&content.grids_table, &content.series_table, &content.differences_table,
                              &content.cost_table, &content.gci_table, &content.failures_table,
                              &content.coverage_table, &content.verdict_count_table}) {
    files.csv.push_back(out_dir / t->file);
    const bool in_parts = content.layout == ReportLayout::summary && (t == &content.grids_table || t == &content.gci_table);
    write_file_atomically(files.csv.back(),
                          in_parts ? (t == &content.grids_table
                                          ? csv_by_series(content.series, grids_table)
                                          : csv_by_series(content.series,
                                                          [&](const std::vector<SeriesSummary>& one) {
                                                            return gci_table(one, data.p_low, data.p_high);
                                                          }))
                                   : to_csv(t->table));
  }
  if (!content.alignment.empty()) {  // only for a study that ran the alignment check
    files.csv.push_back(out_dir / content.alignment_table.file);
    write_file_atomically(files.csv.back(), to_csv(content.alignment_table.table));
  }
  write_stability_files(content, out_dir, files);  // stability.csv, stability_series.csv
  write_ensemble_files(content.ensembles, out_dir, files);  // ensembles.csv, budget.csv, budget_*.svg
  const auto converter = data.export_charts ? find_svg_converter() : std::filesystem::path();
  if (data.export_charts && converter.empty()) {
    content.export_note = "PDF and PNG copies of the charts were not written: rsvg-convert is not installed "
                          "(Debian package librsvg2-bin).";
    spdlog::warn("report: {}", content.export_note);
  }
  for (NamedChart& c : content.charts) {
    check_stop();
    files.svg.push_back(out_dir / c.file);
    const std::string svg = render_svg_file(c.chart);
    // An unchanged chart keeps its PDF/PNG: the report is rewritten after
    // every finished series, most charts stay the same.
    const bool unchanged = !write_if_changed(files.svg.back(), svg);
    if (converter.empty()) continue;
    auto pdf = files.svg.back(), png = files.svg.back();
    pdf.replace_extension(".pdf");
    png.replace_extension(".png");
    if (unchanged && std::filesystem::exists(pdf) && std::filesystem::exists(png))
      c.converted = {pdf.filename().string(), png.filename().string()};
    else
      c.converted = export_chart(converter, files.svg.back(), stop);
  }
  check_stop();
  if (content.layout == ReportLayout::summary) {
    write_series_pages(content, out_dir, files, check_stop);
  } else {
    std::error_code ec;  // a study that shrank to one page keeps no series pages
    std::filesystem::remove_all(out_dir / "series", ec);
  }
  check_stop();
  remove_stale_charts(out_dir, files.svg);
  files.markdown = out_dir / "report.md";
  write_file_atomically(files.markdown, render_markdown(content));
  files.html = out_dir / "report.html";
  write_file_atomically(files.html, render_html(content));
  spdlog::info("report: {} series, {} charts written to {}", content.series.size(), files.svg.size(),
               out_dir.string());
  return files;
}

}  // namespace gridfree
