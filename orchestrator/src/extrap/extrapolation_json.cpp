// SPDX-License-Identifier: GPL-3.0-or-later
// JSON form of an ExtrapolationResult, docs/INTERFACE.md §4 (see extrapolation.h).
// Empty optionals and non-finite numbers become null.
#include <cmath>
#include <optional>
#include <string>

#include "extrap/extrapolation.h"

#include "extrap/bias_checks.h"

namespace gridfree {
namespace {

using ojson = nlohmann::ordered_json;

ojson num(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return nullptr;
  return *v;
}

ojson flag(const std::optional<bool>& v) {
  if (!v) return nullptr;
  return *v;
}

ojson text(const std::optional<std::string>& v) {
  if (!v) return nullptr;
  return *v;
}

ojson power_json(const FitSummary& s) {
  ojson j{{"f0", num(s.f0)}, {"p", num(s.p)}, {"c", num(s.c)}, {"sigma", num(s.sigma)},
          {"p_found", flag(s.p_found)}};
  if (s.weighted) j["weighted"] = *s.weighted;
  return j;
}

ojson fixed_json(const FitSummary& s, bool has_c1, bool has_c2) {
  ojson j{{"f0", num(s.f0)}};
  if (has_c1) j["c1"] = num(s.c1);
  if (has_c2) j["c2"] = num(s.c2);
  j["sigma"] = num(s.sigma);
  if (s.weighted) j["weighted"] = *s.weighted;
  return j;
}

ojson gci_json(const GciTriplet& t) {
  return ojson{{"h", {t.h[0], t.h[1], t.h[2]}},
               {"p", num(t.p)},
               {"f_ext", num(t.f_ext)},
               {"gci_fine", num(t.gci_fine)},
               {"convergence", text(t.convergence)},
               {"status", t.status},
               {"f", {t.f[0], t.f[1], t.f[2]}},
               {"r21", t.r21},
               {"r32", t.r32},
               {"R", num(t.ratio)},
               {"e_a21", num(t.e_a21)},
               {"e_ext21", num(t.e_ext21)},
               {"gci_fine_abs", num(t.gci_fine_abs)},
               {"iterations", t.iterations}};
}

ojson verdict_json(const Verdict& v) {
  const VerdictChecks& c = v.checks;
  return ojson{{"value", v.value},
               {"reasons", v.reasons},
               {"next_h", num(v.next_h)},
               {"checks",
                {{"n_grids", c.n_grids},
                 {"dof", c.dof},
                 {"p", num(c.p)},
                 {"order_in_range", c.order_in_range},
                 {"sigma_over_range", num(c.sigma_over_range)},
                 {"good_fit", c.good_fit},
                 {"envelope", {num(c.envelope_low), num(c.envelope_high)}},
                 {"inside_envelope", c.inside_envelope},
                 {"monotone", c.monotone},
                 {"behind_trend", c.behind_trend},
                 {"rde_finest", num(c.rde_finest)}}}};
}

}  // namespace

nlohmann::ordered_json to_ordered_json(const ExtrapolationResult& r) {
  ojson j;
  j["status"] = r.status;
  j["verdict"] = verdict_json(r.verdict);
  j["method"] = text(r.method);
  j["f0"] = num(r.f0);
  j["u0"] = num(r.u0);
  j["p"] = num(r.p);
  j["sigma_re"] = num(r.sigma_re);
  j["data_range"] = num(r.data_range);
  j["fs"] = num(r.fs);
  j["sigma_over_range"] = num(r.sigma_over_range);
  j["n_grids"] = r.grids.size();

  ojson fits = ojson::object();
  fits["power"] = power_json(r.power.value_or(FitSummary{}));
  fits["mixed"] = fixed_json(r.mixed.value_or(FitSummary{}), true, true);
  if (r.capped)
    fits["capped"] = ojson{{"f0", num(r.capped->f0)}, {"p", num(r.capped->p)}, {"c", num(r.capped->c)},
                           {"sigma", num(r.capped->sigma)}};
  if (r.first) fits["first"] = fixed_json(*r.first, true, false);
  if (r.second) fits["second"] = fixed_json(*r.second, false, true);
  j["fits"] = fits;

  ojson grids = ojson::array();
  for (const auto& g : r.grids)
    grids.push_back(ojson{{"h", g.h}, {"f", g.f}, {"fhat", num(g.fhat)}, {"u", num(g.u)}, {"rde", num(g.rde)}});
  j["grids"] = grids;

  ojson gci = ojson::array();
  for (const auto& t : r.gci) gci.push_back(gci_json(t));
  j["gci"] = gci;

  if (r.eh14)
    j["eh14"] = {{"order_branch", r.eh14->order},
                 {"scatter_branch", r.eh14->scatter},
                 {"error_estimate", r.eh14->error_estimate},
                 {"p_observed", num(r.eh14->p)}};
  if (r.model_spread) j["model_average"] = {{"fits", r.model_spread->fits}, {"f0", r.model_spread->f0}};
  j["bias_checks"] = to_ordered_json(r.bias);
  j["notes"] = r.notes;
  return j;
}

nlohmann::json to_json(const ExtrapolationResult& r) { return nlohmann::json(to_ordered_json(r)); }

}  // namespace gridfree
