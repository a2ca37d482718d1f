// SPDX-License-Identifier: GPL-3.0-or-later
// Reads the contract's extrapolation JSON into an ExtrapolationView.
#include "report/extrap_view.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace gridfree {

namespace {

using nlohmann::json;

// An optional number at obj[key]; null/absent → empty. `where` is the
// JSON pointer of obj, for the error message.
std::optional<double> number(const json& obj, const char* key, const std::string& where) {
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return std::nullopt;
  const json& v = obj.at(key);
  if (!v.is_number()) throw InputError(where + "/" + key, "expected a number or null");
  return v.get<double>();
}

double required_number(const json& obj, const char* key, const std::string& where) {
  auto v = number(obj, key, where);
  if (!v) throw InputError(where + "/" + key, "required number is missing");
  return *v;
}

std::string word(const json& obj, const char* key, const std::string& where) {
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return {};
  const json& v = obj.at(key);
  if (!v.is_string()) throw InputError(where + "/" + key, "expected a string");
  return v.get<std::string>();
}

const json& member(const json& obj, const char* key) {
  static const json empty = json::object();  // immutable default
  return obj.is_object() && obj.contains(key) && obj.at(key).is_object() ? obj.at(key) : empty;
}

const json& array_member(const json& obj, const char* key, const std::string& where) {
  static const json empty = json::array();
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return empty;
  if (!obj.at(key).is_array()) throw InputError(where + "/" + key, "expected an array");
  return obj.at(key);
}

}  // namespace

std::optional<double> ExtrapolationView::fit_quality() const {
  if (!sigma_re || !data_range || !(*data_range > 0)) return std::nullopt;
  return *sigma_re / *data_range;
}

const ExtrapolatedGrid* ExtrapolationView::grid_at(double h) const {
  for (const auto& g : grids) {
    if (std::abs(g.h - h) <= 1e-9 * std::max(std::abs(h), 1e-300)) return &g;
  }
  return nullptr;
}

ExtrapolationView from_json(const json& j) {
  if (!j.is_object()) throw InputError("", "extrapolation result must be a JSON object");
  ExtrapolationView v;
  v.status = word(j, "status", "");
  v.method = word(j, "method", "");
  v.f0 = number(j, "f0", "");
  v.u0 = number(j, "u0", "");
  v.p = number(j, "p", "");
  v.sigma_re = number(j, "sigma_re", "");
  v.data_range = number(j, "data_range", "");
  v.fs = number(j, "fs", "");

  const json& fits = member(j, "fits");
  const json& power = member(fits, "power");
  v.power.f0 = number(power, "f0", "/fits/power");
  v.power.p = number(power, "p", "/fits/power");
  v.power.c = number(power, "c", "/fits/power");
  v.power.sigma = number(power, "sigma", "/fits/power");
  v.power.p_found = power.contains("p_found") && power.at("p_found").is_boolean() &&
                    power.at("p_found").get<bool>();
  const json& mixed = member(fits, "mixed");
  v.mixed.f0 = number(mixed, "f0", "/fits/mixed");
  v.mixed.c1 = number(mixed, "c1", "/fits/mixed");
  v.mixed.c2 = number(mixed, "c2", "/fits/mixed");
  v.mixed.sigma = number(mixed, "sigma", "/fits/mixed");

  const json& grids = array_member(j, "grids", "");
  for (std::size_t i = 0; i < grids.size(); ++i) {
    const std::string where = "/grids/" + std::to_string(i);
    ExtrapolatedGrid g;
    g.h = required_number(grids[i], "h", where);
    g.f = required_number(grids[i], "f", where);
    g.fhat = number(grids[i], "fhat", where);
    g.u = number(grids[i], "u", where);
    g.rde = number(grids[i], "rde", where);
    v.grids.push_back(g);
  }
  std::sort(v.grids.begin(), v.grids.end(),
            [](const ExtrapolatedGrid& a, const ExtrapolatedGrid& b) { return a.h < b.h; });

  const json& gci = array_member(j, "gci", "");
  for (std::size_t i = 0; i < gci.size(); ++i) {
    const std::string where = "/gci/" + std::to_string(i);
    GciView t;
    const json& h = array_member(gci[i], "h", where);
    if (h.size() != 3) throw InputError(where + "/h", "expected three grid sizes");
    for (std::size_t k = 0; k < 3; ++k) {
      if (!h[k].is_number()) throw InputError(where + "/h/" + std::to_string(k), "expected a number");
      t.h[k] = h[k].get<double>();
    }
    t.p = number(gci[i], "p", where);
    t.f_ext = number(gci[i], "f_ext", where);
    t.gci_fine = number(gci[i], "gci_fine", where);
    t.convergence = word(gci[i], "convergence", where);
    t.status = word(gci[i], "status", where);
    v.gci.push_back(t);
  }
  const json& notes = array_member(j, "notes", "");
  for (std::size_t i = 0; i < notes.size(); ++i) {
    if (!notes[i].is_string()) throw InputError("/notes/" + std::to_string(i), "expected a string");
    v.notes.push_back(notes[i].get<std::string>());
  }
  const json& verdict = member(j, "verdict");
  v.verdict = word(verdict, "value", "/verdict");
  v.next_h = number(verdict, "next_h", "/verdict");
  const json& reasons = array_member(verdict, "reasons", "/verdict");
  for (std::size_t i = 0; i < reasons.size(); ++i) {
    if (!reasons[i].is_string())
      throw InputError("/verdict/reasons/" + std::to_string(i), "expected a string");
    v.verdict_reasons.push_back(reasons[i].get<std::string>());
  }
  return v;
}

}  // namespace gridfree
