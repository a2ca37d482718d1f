// SPDX-License-Identifier: GPL-3.0-or-later
// external_ladder, external_expressions (study/external_ladder.h).
#include "study/external_ladder.h"

#include <cmath>

#include "core/json_fields.h"
#include "study/format_number.h"

namespace gridfree {
namespace {

constexpr int kRealSamples = 2001;        // points at which a real variable's h is checked
constexpr double kIntegerSampleAll = 20000;  // an integer range up to this long: every integer
constexpr int kBisections = 200;          // halvings of the range: below a double's resolution

// h with the grid variable at `value` (derived variables recomputed).
double h_at(const ExternalCase& c, const std::string& name, double value) {
  return external_grid(c, {{name, {value}}}, 0).h;
}

std::string value_text(const AdaptiveVariable& v, double x) {
  return v.name + " = " + format_number("%.6g", x);
}

// The variable at fraction t of the way from coarsest to finest.
double along(const AdaptiveVariable& v, double t) { return v.coarsest + t * (v.finest - v.coarsest); }

double four_digits(double x) {
  if (x == 0) return 0;
  const double digits = 4 - std::ceil(std::log10(std::fabs(x)));
  const double scale = std::pow(10.0, digits);
  return std::round(x * scale) / scale;
}

// A problem with h's shape on the range, or "".
std::string monotonicity_problem(const ExternalCase& c, const AdaptiveVariable& v) {
  const double span = std::fabs(v.finest - v.coarsest);
  const int n = v.integer && span <= kIntegerSampleAll ? static_cast<int>(span) : kRealSamples - 1;
  double previous = h_at(c, v.name, v.coarsest);
  double previous_x = v.coarsest;
  for (int i = 1; i <= n; ++i) {
    double x = along(v, static_cast<double>(i) / n);
    if (v.integer) x = std::round(x);
    const double h = h_at(c, v.name, x);
    if (!std::isfinite(h) || !(h > 0))
      return "h = " + c.h_expression + " is " + format_number("%.6g", h) + " at " + value_text(v, x) +
             "; it must be a positive finite number over the ladder's range";
    if (h > previous)
      return "h = " + c.h_expression + " increases from " + format_number("%.6g", previous) + " at " +
             value_text(v, previous_x) + " to " + format_number("%.6g", h) + " at " + value_text(v, x) +
             ": an adaptive series needs h to fall monotonically from " + value_text(v, v.coarsest) + " to " +
             value_text(v, v.finest) + " to find the " + v.name + " of each wanted h";
    previous = h;
    previous_x = x;
  }
  if (!(previous < h_at(c, v.name, v.coarsest)))
    return "h = " + c.h_expression + " is the same at " + value_text(v, v.coarsest) + " and " +
           value_text(v, v.finest) + ": the ladder needs h to fall from coarsest to finest";
  return "";
}

// The variable's value whose h is closest to `wanted` (h non-increasing along t).
double invert(const ExternalCase& c, const AdaptiveVariable& v, double wanted) {
  double lo = 0, hi = 1;  // h(lo) > wanted ≥ h(hi), as far as the ends allow
  for (int i = 0; i < kBisections && hi - lo > 0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (h_at(c, v.name, along(v, mid)) > wanted ? lo : hi) = mid;
  }
  const double x = along(v, hi);
  if (!v.integer) {
    const double r = four_digits(x);
    const double low = std::min(v.coarsest, v.finest), high = std::max(v.coarsest, v.finest);
    return std::min(high, std::max(low, r));
  }
  // The nearer of the two integers in log h.
  const double a = std::floor(x), b = std::ceil(x);
  const double da = std::fabs(std::log(h_at(c, v.name, a) / wanted));
  const double db = std::fabs(std::log(h_at(c, v.name, b) / wanted));
  return db < da ? b : a;
}

}  // namespace

ExternalLadder external_ladder(const ExternalCase& c, const AdaptiveVariable& v, double ratio,
                               const std::string& case_name, ProblemList& problems) {
  const std::string case_at = child_pointer("/cases", case_name) + "/external";
  ExternalLadder out;
  try {
    if (const std::string why = monotonicity_problem(c, v); !why.empty()) {
      problems.add(case_at + "/h", why);
      return {};
    }
    const double h0 = h_at(c, v.name, v.coarsest), h_end = h_at(c, v.name, v.finest);
    std::vector<double>& values = out.variables[v.name];
    for (int k = 0; k < 10000; ++k) {
      const double wanted = h0 / std::pow(ratio, k);
      if (wanted < h_end * (1 - 1e-9)) break;
      const double x = k == 0 ? v.coarsest : invert(c, v, wanted);
      if (!values.empty() && h_at(c, v.name, x) >= h_at(c, v.name, values.back())) {
        problems.add("/grids/ratio", "ladder rungs " + std::to_string(k) + " and " + std::to_string(k + 1) +
                                         " of case " + case_name + " (h " +
                                         format_number("%.4g", out.h_nominal.back()) + " and " +
                                         format_number("%.4g", wanted) + ") both come out at " + value_text(v, x) +
                                         " after rounding; take a larger ratio or a finer coarsest grid");
        return {};
      }
      out.h_nominal.push_back(wanted);
      values.push_back(x);
    }
  } catch (const std::exception& e) {
    problems.add(case_at, std::string(e.what()) + " (on the adaptive ladder of /grids/variables/" + v.name + ")");
    return {};
  }
  if (out.h_nominal.size() < AdaptiveGrids::kMinLadder) {
    problems.add("/grids/variables/" + v.name + "/finest",
                 "the ladder from h = " + format_number("%.4g", out.h_nominal.empty() ? 0.0 : out.h_nominal.front()) +
                     " by ratio " + format_number("%.4g", ratio) + " down to h = " +
                     format_number("%.4g", h_at(c, v.name, v.finest)) + " (" + value_text(v, v.finest) + ") holds " +
                     std::to_string(out.h_nominal.size()) + " grids; a converged verdict needs " +
                     std::to_string(AdaptiveGrids::kMinLadder));
    return {};
  }
  return out;
}

ExternalCase external_expressions(const nlohmann::json& ext) {
  ExternalCase c;
  if (!ext.is_object()) return c;
  if (auto v = ext.find("variables"); v != ext.end() && v->is_object())
    for (auto it = v->begin(); it != v->end(); ++it)
      if (it->is_string()) c.variables[it.key()] = it->get<std::string>();
  if (auto h = ext.find("h"); h != ext.end()) {
    c.h_expression = external_h_expression(*h, &c.h_meaning);
    if (h->is_object() && h->contains("cells") && (*h)["cells"].is_string()) c.cells_expression = (*h)["cells"];
  }
  if (auto n = ext.find("cells"); n != ext.end() && n->is_string()) c.cells_expression = n->get<std::string>();
  if (auto cost = ext.find("cost"); cost != ext.end() && cost->is_object()) {
    if (auto x = cost->find("cpu_s_per_cell"); x != cost->end() && x->is_number()) c.cpu_s_per_cell = x->get<double>();
    if (auto x = cost->find("mb_per_cell"); x != cost->end() && x->is_number()) c.mb_per_cell = x->get<double>();
  }
  return c;
}

}  // namespace gridfree
