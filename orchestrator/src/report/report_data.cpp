// SPDX-License-Identifier: GPL-3.0-or-later
// SeriesData::label: the short name a series goes by in tables and legends.
#include "report/report_data.h"

#include "report/text_format.h"

namespace gridfree {

// "PC1 superbee fwhm6 bvk"; a centroid-deposition series shows "centroid"
// instead of the (unused) filter width, and any other non-default
// deposition is appended.
std::string SeriesData::value_axis() const {
  return quantity.empty() ? "DP* = Δp / (ρ_{g} U_{0}^{2})" : quantity_label;
}

std::string SeriesData::h_axis() const {
  return quantity.empty() ? "Δ* (cell size / particle diameter)" : h_label;
}

std::string SeriesData::label() const {
  if (!quantity.empty()) {  // "cavity scheme=QUICK kinetic_energy"
    std::string out = case_name;
    for (const auto& [name, level] : levels) out += " " + name + "=" + level;
    return out + " " + quantity;
  }
  std::string out = case_name + " " + convection + " ";
  if (deposition == "centroid") {
    out += "centroid";
  } else {
    out += "fwhm" + format_g(fwhm_dp, 6);
  }
  out += " " + drag;
  if (!deposition.empty() && deposition != "diffusion" && deposition != "centroid") {
    out += " " + deposition;
  }
  return out;
}

}  // namespace gridfree
