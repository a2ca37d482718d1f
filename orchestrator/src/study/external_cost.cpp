// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates of external jobs (study/external_cost.h).
#include "study/external_cost.h"

#include <algorithm>

#include "study/format_number.h"

namespace gridfree {
namespace {

using Points = std::vector<std::pair<double, double>>;  // (cells, measured)

// Cell counts closer than this (relative) are one size.
constexpr double kSameSize = 1e-9;

bool same_size(double a, double b) { return std::fabs(a - b) <= kSameSize * std::max(a, b); }

std::size_t distinct_sizes(Points xy) {
  std::sort(xy.begin(), xy.end());
  std::size_t n = 0;
  for (std::size_t i = 0; i < xy.size(); ++i)
    if (i == 0 || !same_size(xy[i].first, xy[i - 1].first)) ++n;
  return n;
}

// The largest measured value at as many cells as `cells` or fewer (0: none).
double largest_at_or_below(const Points& xy, double cells) {
  double m = 0;
  for (const auto& [x, y] : xy)
    if (x <= cells * (1 + kSameSize)) m = std::max(m, y);
  return m;
}

// The means of x and y and the sums of squares about them.
struct LineSums {
  double mx = 0, my = 0, sxx = 0, sxy = 0;
};

LineSums line_sums(const Points& xy) {
  LineSums s;
  for (const auto& [x, y] : xy) {
    s.mx += x;
    s.my += y;
  }
  s.mx /= static_cast<double>(xy.size());
  s.my /= static_cast<double>(xy.size());
  for (const auto& [x, y] : xy) {
    s.sxx += (x - s.mx) * (x - s.mx);
    s.sxy += (x - s.mx) * (y - s.my);
  }
  return s;
}

std::string cells_text(double c) { return format_number("%.0f", c); }

// One measured size: its figure at or below it, unknown above (file comment).
void one_size(CostFit& f, const Points& xy, double cells, const std::string& what, const std::string& measured,
              const std::string& unit_text) {
  const double c1 = xy.front().first;
  if (cells <= c1 * (1 + kSameSize)) {
    f.value = largest_at_or_below(xy, c1);
    f.basis = "history: the " + what + " measured at " + cells_text(c1) + " cells (" + measured +
              "; one measured size), for a grid no larger";
  } else {
    f.basis = "unknown above " + cells_text(c1) + " cells: one measured size (" + measured + " at " +
              cells_text(c1) + " cells) cannot tell a fixed " + unit_text +
              " from what grows with cells; the next larger grid gives a second size";
  }
}

Points usable(const std::vector<CostSample>& samples, bool memory) {
  Points xy;
  for (const auto& s : samples) {
    const double y = memory ? s.peak_rss_mb : s.cpu_s;
    if (s.cells > 0 && y > 0 && std::isfinite(y)) xy.emplace_back(s.cells, y);
  }
  return xy;
}

std::string job_count_text(const CostFit& f) {
  return std::to_string(f.samples) + " finished job(s) of the case at " + std::to_string(f.sizes) + " sizes";
}

// The fixed part the measured samples show beyond a declared per-cell
// figure: max over them of measured − per_cell × cells, at least 0.
double fixed_beyond(const Points& xy, double per_cell) {
  double fixed = 0;
  for (const auto& [x, y] : xy) fixed = std::max(fixed, y - per_cell * x);
  return fixed;
}

}  // namespace

CostFit fit_cpu_seconds(const std::vector<CostSample>& samples, double cells) {
  CostFit f;
  const Points xy = usable(samples, false);
  f.samples = xy.size();
  f.sizes = distinct_sizes(xy);
  if (xy.empty() || !(cells > 0)) {
    f.basis = "unknown (no cost.cpu_s_per_cell and no finished job of the case yet)";
    return f;
  }
  if (f.sizes == 1) {
    one_size(f, xy, cells, "CPU time", format_number("%.3g", largest_at_or_below(xy, xy.front().first)) + " CPU s",
             "start-up time");
    return f;
  }
  Points logs;
  for (const auto& [x, y] : xy) logs.emplace_back(std::log(x), std::log(y));
  const auto [mx, my, sxx, sxy] = line_sums(logs);
  f.exponent = sxy / sxx;
  if (f.exponent < 0) {  // times falling with cells: start-up noise; the largest measured time
    f.exponent = 0;
    f.value = largest_at_or_below(xy, HUGE_VAL);
    f.basis = "history: " + job_count_text(f) + ", the largest measured CPU time (the times do not grow with cells)";
    return f;
  }
  f.value = std::max(std::exp(my + f.exponent * (std::log(cells) - mx)), largest_at_or_below(xy, cells));
  f.basis = "history: " + job_count_text(f) + ", CPU s ∝ cells^" + format_number("%.2f", f.exponent);
  return f;
}

CostFit fit_memory_mb(const std::vector<CostSample>& samples, double cells) {
  CostFit f;
  const Points xy = usable(samples, true);
  f.samples = xy.size();
  f.sizes = distinct_sizes(xy);
  if (xy.empty() || !(cells > 0)) {
    f.basis = "unknown (no cost.mb_per_cell and no finished job of the case yet)";
    return f;
  }
  if (f.sizes == 1) {
    one_size(f, xy, cells, "peak memory", format_number("%.0f", largest_at_or_below(xy, xy.front().first)) + " MiB",
             "footprint");
    if (std::isfinite(f.value)) f.basis += ", x " + format_number("%g", kExternalMemorySafety);
    return f;
  }
  const auto [mx, my, sxx, sxy] = line_sums(xy);
  double b = sxy / sxx, a = my - b * mx;
  if (b < 0) {  // memory falling with cells: noise; the largest peak
    b = 0;
    a = 0;
    for (const auto& [x, y] : xy) a = std::max(a, y);
  } else if (a < 0) {  // through the origin
    double sxy0 = 0, sxx0 = 0;
    for (const auto& [x, y] : xy) {
      sxy0 += x * y;
      sxx0 += x * x;
    }
    a = 0;
    b = sxy0 / sxx0;
  }
  f.fixed = a;
  f.per_cell = b;
  f.value = std::max(a + b * cells, largest_at_or_below(xy, cells));
  double largest = 0, at = 0;
  for (const auto& [x, y] : xy)
    if (y > largest) {
      largest = y;
      at = x;
    }
  f.basis = "history: peak memory of " + job_count_text(f) + " (largest " + format_number("%.0f", largest) +
            " MiB at " + cells_text(at) + " cells): " + format_number("%.3g", a) + " MiB + " +
            format_number("%.3g", b) + " MiB per cell, x " + format_number("%g", kExternalMemorySafety);
  return f;
}

ExternalJobCost external_job_estimate(std::optional<double> cpu_s_per_cell, std::optional<double> mb_per_cell,
                                      const std::vector<CostSample>* samples, double cells) {
  static const std::vector<CostSample> kNone;
  const std::vector<CostSample>& measured = samples == nullptr ? kNone : *samples;
  ExternalJobCost out;
  if (mb_per_cell) {
    const Points xy = usable(measured, true);
    const double fixed = fixed_beyond(xy, *mb_per_cell);
    out.memory_bytes = (kExternalMemorySafety * fixed + *mb_per_cell * cells) * 1024 * 1024;
    out.memory_basis = "declared " + format_number("%.3g", *mb_per_cell) + " MB per cell";
    if (!xy.empty())
      out.memory_basis += " + the fixed footprint the case's " + std::to_string(xy.size()) + " finished job(s) show (" +
                          format_number("%.0f", fixed) + " MiB, x " + format_number("%g", kExternalMemorySafety) + ")";
  } else {
    const CostFit m = fit_memory_mb(measured, cells);
    out.memory_bytes = kExternalMemorySafety * m.value * 1024 * 1024;  // NaN stays NaN
    out.memory_basis = m.basis;
  }
  if (cpu_s_per_cell) {
    const Points xy = usable(measured, false);
    const double fixed = fixed_beyond(xy, *cpu_s_per_cell);
    out.cpu_s = fixed + *cpu_s_per_cell * cells;
    out.basis = "declared " + format_number("%.3g", *cpu_s_per_cell) + " CPU s per cell";
    if (!xy.empty())
      out.basis += " + the fixed time the case's " + std::to_string(xy.size()) + " finished job(s) show (" +
                   format_number("%.3g", fixed) + " s)";
  } else {
    const CostFit c = fit_cpu_seconds(measured, cells);
    out.cpu_s = c.value;
    out.basis = c.basis;
  }
  return out;
}

std::map<std::string, DeclaredCost> declared_external_costs(const nlohmann::json& definition) {
  std::map<std::string, DeclaredCost> out;
  if (!definition.is_object() || !definition.contains("cases") || !definition["cases"].is_object()) return out;
  for (const auto& [name, c] : definition["cases"].items()) {
    if (!c.is_object() || !c.contains("external")) continue;
    DeclaredCost& d = out[name];
    const auto cpu = nlohmann::json::json_pointer("/external/cost/cpu_s_per_cell");
    const auto mb = nlohmann::json::json_pointer("/external/cost/mb_per_cell");
    if (c.contains(cpu) && c.at(cpu).is_number()) d.cpu_s_per_cell = c.at(cpu).get<double>();
    if (c.contains(mb) && c.at(mb).is_number()) d.mb_per_cell = c.at(mb).get<double>();
  }
  return out;
}

}  // namespace gridfree
