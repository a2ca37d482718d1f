// SPDX-License-Identifier: GPL-3.0-or-later
// Small Study / SeriesKey helpers (labels, look-ups, Δ* of a grid).
#include "study/study.h"

#include <cmath>
#include <cstdio>

namespace gridfree {

std::string SeriesKey::label() const {
  if (external()) {
    std::string out = case_name;
    for (const auto& [name, level] : levels) out += " " + name + "=" + level;
    return out + " " + quantity;
  }
  char fwhm[32];
  std::snprintf(fwhm, sizeof fwhm, "%g", fwhm_dp);
  std::string out = case_name + " " + convection + " fwhm" + fwhm + " " + drag;
  if (deposition != "diffusion") out += " " + deposition;
  return out;
}

std::string levels_json(const std::map<std::string, std::string>& levels) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, level] : levels) j[name] = level;
  return j.dump();
}

std::map<std::string, std::string> levels_from_json(const std::string& text) {
  std::map<std::string, std::string> out;
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return out;
  for (const auto& [name, level] : j.items())
    if (level.is_string()) out[name] = level.get<std::string>();
  return out;
}

const GridVariables& external_grids_of(const Study& study, const std::string& case_name) {
  const auto it = study.external_ladders.find(case_name);
  return it != study.external_ladders.end() ? it->second.variables : study.grid_variables;
}

const StudyCase* Study::find_case(const std::string& n) const {
  for (const auto& c : cases)
    if (c.name == n) return &c;
  return nullptr;
}

std::string Study::design_description() const {
  if (!baseline) return "factorial";
  if (external()) {  // case and levels; every quantity is in the design
    std::string out = baseline->case_name;
    for (const auto& [name, level] : baseline->levels) out += " " + name + "=" + level;
    return "one_at_a_time (baseline " + out + ")";
  }
  return "one_at_a_time (baseline " + baseline->label() + ")";
}

double delta_star_of(const std::array<double, 3>& domain_dp, const std::array<int, 3>& cells) {
  const double v = domain_dp[0] * domain_dp[1] * domain_dp[2];
  const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
  return std::cbrt(v / n);
}

}  // namespace gridfree
