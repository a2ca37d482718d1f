// SPDX-License-Identifier: GPL-3.0-or-later
// Coverage self-check (see self_check.h).
#include "extrap/self_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "extrap/verdict.h"

namespace gridfree {
namespace {

bool usable(const std::optional<double>& v) { return v && std::isfinite(*v); }

std::string percent_of(int k, int n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f %%", 100.0 * k / n);
  return buf;
}

// Judges one window against the reference.
void judge_window(CoverageWindow& w, double reference) {
  const WindowFit& fit = w.fit;
  if (!usable(fit.f1) || !usable(fit.u1)) return;
  const double miss = std::fabs(reference - *fit.f1);
  w.covered = miss <= *fit.u1;
  if (*fit.u1 > 0) w.distance = miss / *fit.u1;
  if (usable(fit.f0) && usable(fit.u0)) w.f0_covered = std::fabs(reference - *fit.f0) <= *fit.u0;
}

}  // namespace

CoverageCheck coverage_self_check(const std::vector<double>& h, const std::vector<double>& f,
                                  const WindowExtrapolator& extrapolate, const CoverageRules& rules) {
  CoverageCheck out;
  out.promised = rules.promised;
  const std::size_t n = h.size();
  if (n < rules.min_series || f.size() != n) {
    out.status = "too_few_grids";
    return out;
  }
  const WindowFit whole = extrapolate(h, f);
  out.reference_verdict = whole.verdict;
  if (!usable(whole.f0)) {
    out.status = "no_reference";
    return out;
  }
  out.status = "checked";
  out.reference = whole.f0;
  out.order_consistent = whole.order_consistent;
  out.leave_one_out_agree = whole.leave_one_out_agree;

  // Windows among grids 1 … n−1 (the finest grid, index 0, is left out).
  for (std::size_t count = rules.min_window; count <= std::min(n - 1, rules.max_window); ++count) {
    for (std::size_t first = 1; first + count <= n; ++first) {
      CoverageWindow w;
      w.first = first;
      w.count = count;
      w.h_fine = h[first];
      w.h_coarse = h[first + count - 1];
      const std::vector<double> wh(h.begin() + first, h.begin() + first + count);
      const std::vector<double> wf(f.begin() + first, f.begin() + first + count);
      w.fit = extrapolate(wh, wf);
      judge_window(w, *out.reference);
      if (w.covered) {
        ++out.judged;
        if (*w.covered) ++out.covered;
        if (w.f0_covered.value_or(false)) ++out.f0_covered;
      }
      out.windows.push_back(std::move(w));
    }
  }
  return out;
}

bool CoverageCheck::below_promise() const {
  return judged > 0 && static_cast<double>(covered) < promised * judged;
}

bool CoverageCheck::bias_failed() const {
  return order_consistent == std::optional<bool>(false) || leave_one_out_agree == std::optional<bool>(false);
}

bool CoverageCheck::flagged() const { return below_promise() || bias_failed(); }

void demote_if_flagged(const CoverageCheck& check, const std::vector<double>& h, Verdict& v,
                       const std::string& h_symbol) {
  if (v.value != "converged" || !check.flagged()) return;
  demote_to_pre_asymptotic({"the coverage self-check flags the series: " + check.summary()}, h, v, h_symbol);
}

WindowFit window_fit(const ExtrapolationResult& r) {
  WindowFit fit;
  fit.verdict = r.verdict.value;
  fit.f0 = r.f0;
  fit.u0 = r.u0;
  fit.order_consistent = r.bias.order_consistent;
  fit.leave_one_out_agree = r.bias.leave_one_out_agree;
  if (!r.grids.empty()) {
    fit.f1 = r.grids.front().f;
    fit.u1 = r.grids.front().u;
  }
  return fit;
}

namespace {

nlohmann::ordered_json number_or_null(const std::optional<double>& v) {
  return usable(v) ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json flag_or_null(const std::optional<bool>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json to_ordered_json(const CoverageCheck& c) {
  using ojson = nlohmann::ordered_json;
  ojson windows = ojson::array();
  for (const auto& w : c.windows)
    windows.push_back(ojson{{"h_fine", w.h_fine},
                            {"h_coarse", w.h_coarse},
                            {"n_grids", w.count},
                            {"verdict", w.fit.verdict},
                            {"f0", number_or_null(w.fit.f0)},
                            {"u0", number_or_null(w.fit.u0)},
                            {"f1", number_or_null(w.fit.f1)},
                            {"u1", number_or_null(w.fit.u1)},
                            {"distance", number_or_null(w.distance)},
                            {"covered", flag_or_null(w.covered)},
                            {"f0_covered", flag_or_null(w.f0_covered)}});
  return ojson{{"status", c.status},
               {"reference", number_or_null(c.reference)},
               {"reference_verdict", c.reference_verdict},
               {"judged", c.judged},
               {"covered", c.covered},
               {"f0_covered", c.f0_covered},
               {"promised", c.promised},
               {"below_promise", c.below_promise()},
               {"order_consistent", flag_or_null(c.order_consistent)},
               {"leave_one_out_agree", flag_or_null(c.leave_one_out_agree)},
               {"flagged", c.flagged()},
               {"summary", c.summary()},
               {"shows", kSelfCheckShows},
               {"windows", windows}};
}

namespace {

std::optional<double> number_at(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

std::optional<bool> flag_at(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_boolean()) return std::nullopt;
  return j[key].get<bool>();
}

}  // namespace

CoverageCheck coverage_from_json(const nlohmann::json& j) {
  CoverageCheck c;
  c.status = j.value("status", std::string());
  c.reference = number_at(j, "reference");
  c.reference_verdict = j.value("reference_verdict", std::string());
  c.judged = j.value("judged", 0);
  c.covered = j.value("covered", 0);
  c.f0_covered = j.value("f0_covered", 0);
  c.promised = j.value("promised", 0.95);
  c.order_consistent = flag_at(j, "order_consistent");
  c.leave_one_out_agree = flag_at(j, "leave_one_out_agree");
  if (!j.contains("windows") || !j["windows"].is_array()) return c;
  for (const auto& w : j["windows"]) {
    CoverageWindow win;
    win.h_fine = number_at(w, "h_fine").value_or(0.0);
    win.h_coarse = number_at(w, "h_coarse").value_or(0.0);
    win.count = w.value("n_grids", std::size_t{0});
    win.fit = {w.value("verdict", std::string()), number_at(w, "f0"), number_at(w, "u0"), number_at(w, "f1"),
               number_at(w, "u1"), {}, {}};
    win.distance = number_at(w, "distance");
    win.covered = flag_at(w, "covered");
    win.f0_covered = flag_at(w, "f0_covered");
    c.windows.push_back(std::move(win));
  }
  return c;
}

std::string CoverageCheck::summary() const {
  if (status == "too_few_grids") return "coverage not checked: it needs at least 6 converged grids";
  if (status == "no_reference") return "coverage not checked: the whole series has no extrapolated value";
  if (judged == 0) return "coverage not checked: no coarser window of 4 or more grids printed an uncertainty";
  std::string s = "U₁ covered the whole series' f0 in " + std::to_string(covered) + " of " + std::to_string(judged) +
                  " coarser windows (" + percent_of(covered, judged) + "); f0 ± U₀ in " +
                  std::to_string(f0_covered) + " of " + std::to_string(judged);
  if (below_promise()) s += ": below the " + percent_of(static_cast<int>(std::lround(promised * 100)), 100) +
                            " the method was measured to reach";
  if (order_consistent == std::optional<bool>(false))
    s += "; the observed order contradicts the declared one";
  if (leave_one_out_agree == std::optional<bool>(false))
    s += "; the fits without the coarsest and without the finest grid disagree beyond U₀";
  return s;
}

}  // namespace gridfree
