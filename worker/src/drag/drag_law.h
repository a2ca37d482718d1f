// SPDX-License-Identifier: GPL-3.0-or-later
// Gas-particle drag laws (PHYSICS.md §4), as pure functions.
//
// Every law returns D, the drag coefficient per unit particle volume
// (g/(cm^3 s)), so that the force on one particle is f_p (u - v_p) with
// f_p = D V_p, and the interphase momentum coefficient is β = ε_s D
// (MFiX Model A). Re → 0 is safe: each law takes its limit, never 0/0.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

enum class DragLaw { kWenYu, kGidaspow, kGidaspowBlend, kBvk, kHkl, kSyamlalObrien };

struct DragState {
  double eps_g = 1;   // gas volume fraction ε_g, in (0, 1]
  double slip = 0;    // |u - v_p|, cm/s, >= 0
  double d = 0;       // particle diameter, cm
  double rho_g = 0;   // gas density, g/cm^3
  double mu_g = 0;    // gas viscosity, g/(cm s)
};

// D for the given law and state (g/(cm^3 s)).
double drag_coefficient(DragLaw law, const DragState& s);

struct DragLawInfo {
  DragLaw law;
  std::string_view name;       // the JSON name, e.g. "bvk"
  std::string_view reference;  // citation
  std::string_view validity;   // range where the correlation was fitted
};

const std::vector<DragLawInfo>& drag_laws();
std::optional<DragLaw> drag_law_from_name(std::string_view name);
std::string_view drag_law_name(DragLaw law);
// "bvk, gidaspow, ..." for error messages.
std::string drag_law_names();

}  // namespace gridfree
