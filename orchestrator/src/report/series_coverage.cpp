// SPDX-License-Identifier: GPL-3.0-or-later
// Coverage self-check in the report (see series_coverage.h).
#include "report/series_coverage.h"

#include <algorithm>
#include <exception>
#include <utility>

#include <spdlog/spdlog.h>

#include "report/series_vocabulary.h"
#include "report/series_summary.h"
#include "extrap/value_format.h"
#include "report/text_format.h"

namespace gridfree {

WindowFit window_fit(const ExtrapolationView& view) {
  WindowFit fit;
  fit.verdict = view.verdict;
  fit.f0 = view.f0;
  fit.u0 = view.u0;
  if (!view.grids.empty()) {
    fit.f1 = view.grids.front().f;
    fit.u1 = view.grids.front().u;
  }
  return fit;
}

namespace {

// The check on sorted grids, the whole fit given.
CoverageCheck check_sorted(const std::vector<double>& h, const std::vector<double>& f, const WindowFit& whole,
                           const Extrapolator& extrapolate) {
  return coverage_self_check(h, f, [&](const std::vector<double>& wh, const std::vector<double>& wf) {
    return wh.size() == h.size() ? whole : window_fit(from_json(extrapolate(wh, wf)));
  });
}

}  // namespace

std::optional<CoverageCheck> coverage_of(const std::vector<double>& h, const std::vector<double>& f,
                                         const nlohmann::json& whole, const Extrapolator& extrapolate) {
  if (h.size() < CoverageRules{}.min_series || h.size() != f.size() || !extrapolate) return std::nullopt;
  std::vector<std::pair<double, double>> grids;
  for (std::size_t i = 0; i < h.size(); ++i) grids.emplace_back(h[i], f[i]);
  std::sort(grids.begin(), grids.end());
  std::vector<double> hs, fs;
  for (const auto& [hi, fi] : grids) hs.push_back(hi), fs.push_back(fi);
  WindowFit fit = window_fit(from_json(whole));
  if (!fit.f0) return std::nullopt;
  // The whole series' bias tests (extrap/bias_checks.h) travel with its check.
  if (whole.contains("bias_checks") && whole["bias_checks"].is_object()) {
    const auto& b = whole["bias_checks"];
    if (b.contains("order_consistent") && b["order_consistent"].is_boolean())
      fit.order_consistent = b["order_consistent"].get<bool>();
    if (b.contains("leave_one_out_agree") && b["leave_one_out_agree"].is_boolean())
      fit.leave_one_out_agree = b["leave_one_out_agree"].get<bool>();
  }
  return check_sorted(hs, fs, fit, extrapolate);
}

std::optional<CoverageCheck> series_coverage(const SeriesSummary& s, const Extrapolator& extrapolate) {
  if (s.incomplete || !s.extrapolation || s.h.size() < CoverageRules{}.min_series) return std::nullopt;
  if (s.series.stored_coverage) return s.series.stored_coverage;
  if (!extrapolate) return std::nullopt;
  try {
    return check_sorted(s.h, s.f, window_fit(*s.extrapolation), extrapolate);
  } catch (const std::exception& e) {
    spdlog::warn("report: coverage self-check of series {} failed: {}", s.label, e.what());
    return std::nullopt;
  }
}

std::string missed_windows(const CoverageCheck& c, const std::string& h_symbol) {
  std::string out;
  for (auto it = c.windows.rbegin(); it != c.windows.rend(); ++it) {
    if (!it->covered || *it->covered) continue;
    if (!out.empty()) out += "; ";
    out += h_symbol + " " + format_cell_size(it->h_coarse) + "–" + format_cell_size(it->h_fine);
    if (it->distance) out += " (" + format_g(*it->distance, 2) + " U₁)";
  }
  return out;
}

std::optional<double> worst_distance(const CoverageCheck& c) {
  std::optional<double> worst;
  for (const auto& w : c.windows)
    if (w.distance) worst = std::max(worst.value_or(0.0), *w.distance);
  return worst;
}

std::optional<double> coverage_rate(const CoverageCheck& c) {
  if (c.judged == 0) return std::nullopt;
  return static_cast<double>(c.covered) / c.judged;
}

std::string coverage_not_made(const std::vector<SeriesSummary>& series) {
  int unfinished = 0, most = 0;
  for (const auto& s : series) {
    if (s.incomplete) ++unfinished;
    most = std::max(most, s.converged());
  }
  const std::string need = "a series needs all its grids and at least " + std::to_string(CoverageRules{}.min_series) +
                           " of them converged";
  if (unfinished > 0)
    return "not yet made (" + need + "; " + std::to_string(unfinished) + " of " + std::to_string(series.size()) +
           " series still have grids to run)";
  return "not made, and it cannot be with these grids: " + need + ", and the most any series has is " +
         std::to_string(most) + " (add finer grids to have it)";
}

std::string coverage_summary(const std::vector<SeriesSummary>& series) {
  int checked = 0, judged = 0, covered = 0, below = 0;
  for (const auto& s : series) {
    if (!s.coverage || s.coverage->judged == 0) continue;
    ++checked;
    judged += s.coverage->judged;
    covered += s.coverage->covered;
    below += s.coverage->below_promise() ? 1 : 0;
  }
  if (checked == 0) return coverage_not_made(series);
  return "U₁ covered the full series' f0 in " + std::to_string(covered) + " of " + std::to_string(judged) +
         " coarser windows of " + std::to_string(checked) + " series; " + std::to_string(below) +
         " series below 95 %";
}

std::vector<std::string> coverage_warnings(const std::vector<SeriesSummary>& series) {
  std::vector<std::string> out;
  for (const auto& s : series) {
    if (!s.coverage || !s.coverage->below_promise()) continue;
    out.push_back(s.label + ": " + s.coverage->summary() + "; missed: " + missed_windows(*s.coverage, series_vocabulary(s.series).h_symbol) +
                  ". Its U may be too narrow on coarse grids: look at the coverage table before trusting it.");
  }
  return out;
}

}  // namespace gridfree
