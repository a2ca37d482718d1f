// SPDX-License-Identifier: GPL-3.0-or-later
// Fit windows of adaptive series (sched/adaptive_window.h).
#include "sched/adaptive_window.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace gridfree {
namespace {

std::string verdict_of(const nlohmann::json& ex) {
  if (ex.is_object() && ex.contains("verdict") && ex["verdict"].is_object() && ex["verdict"].contains("value") &&
      ex["verdict"]["value"].is_string())
    return ex["verdict"]["value"].get<std::string>();
  return "";
}

std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

WindowedFit windowed_extrapolation(const std::vector<double>& h, const std::vector<double>& f,
                                   const Extrapolator& extrapolate) {
  if (h.size() != f.size() || h.size() < 2) throw std::invalid_argument("windowed_extrapolation: need ≥ 2 (h, f) pairs");
  // Finest first.
  std::vector<std::size_t> order(h.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] < h[b]; });
  auto fit_finest = [&](std::size_t k) {
    std::vector<double> hk, fk;
    for (std::size_t i = 0; i < k; ++i) {
      hk.push_back(h[order[i]]);
      fk.push_back(f[order[i]]);
    }
    return extrapolate(hk, fk);
  };
  const std::size_t n = h.size();
  WindowedFit w;
  w.extrapolation = fit_finest(n);
  w.used = n;
  w.full_set_verdict = verdict_of(w.extrapolation);
  w.finest_h = h[order.front()];
  w.coarsest_used_h = h[order.back()];
  if (w.full_set_verdict == "converged") return w;
  for (std::size_t k = n - 1; k >= kMinWindowGrids && k < n; --k) {
    nlohmann::json ex = fit_finest(k);
    if (verdict_of(ex) != "converged") continue;
    w.extrapolation = std::move(ex);
    w.used = k;
    w.left_out = n - k;
    w.coarsest_used_h = h[order[k - 1]];
    break;
  }
  return w;
}

std::string window_sentence(const WindowedFit& w, const std::string& h_symbol) {
  if (w.left_out == 0) return "";
  return "fit on the " + std::to_string(w.used) + " finest grids, " + h_symbol + " " + g3(w.coarsest_used_h) + " → " +
         g3(w.finest_h) + "; the " + std::to_string(w.left_out) + " coarser one" + (w.left_out == 1 ? " was" : "s were") +
         " left out (the fit on all " + std::to_string(w.used + w.left_out) + " was " +
         (w.full_set_verdict.empty() ? std::string("not made") : w.full_set_verdict) + ")";
}

Extrapolator windowed_extrapolator(Extrapolator base) {
  return [base = std::move(base)](const std::vector<double>& h, const std::vector<double>& f) {
    return windowed_extrapolation(h, f, base).extrapolation;
  };
}

}  // namespace gridfree
