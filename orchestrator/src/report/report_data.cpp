// SPDX-License-Identifier: GPL-3.0-or-later
// SeriesData::label: the short name a series goes by in tables and legends.
#include "report/report_data.h"

#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

// "PC1 superbee fwhm6 bvk"; a centroid-deposition series shows "centroid"
// instead of the (unused) filter width, and any other non-default
// deposition is appended.
std::string SeriesData::value_axis() const { return series_vocabulary(*this).quantity_meaning; }

std::string SeriesData::h_axis() const { return series_vocabulary(*this).h_meaning; }

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
