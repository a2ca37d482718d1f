// ε_s from particles: centroid deposition, optional Gaussian filter (see header).
#include "coupling/solids_fraction.h"

#include <cstdio>

#include "deposition/centroid.h"

namespace gridfree {
namespace {

void find_max(SolidsFraction& sf) {
  sf.max = 0;
  sf.argmax = 0;
  for (std::size_t c = 0; c < sf.eps_s.size(); ++c)
    if (sf.eps_s[c] > sf.max) {
      sf.max = sf.eps_s[c];
      sf.argmax = c;
    }
}

}  // namespace

FilterSettings filter_settings(const DepositionSpec& deposition, double d, double tolerance) {
  FilterSettings s;
  s.fwhm_cm = deposition.fwhm_dp * d;
  s.diffusivity = deposition.diffusivity;
  s.tolerance = tolerance;
  return s;
}

SolidsFraction deposit_solids_fraction(const Grid& grid, const std::vector<Particle>& particles,
                                       const DepositionSpec& deposition, double d,
                                       double filter_tolerance) {
  SolidsFraction sf;
  sf.eps_s = solids_fraction_centroid(grid, particles);
  if (deposition.kind == DepositionKind::kDiffusion) {
    sf.filter = apply_filter(grid, filter_settings(deposition, d, filter_tolerance), sf.eps_s);
    sf.filtered = true;
  }
  find_max(sf);
  return sf;
}

SolidsFraction uniform_solids_fraction(const Grid& grid, double phi) {
  SolidsFraction sf;
  sf.eps_s.assign(grid.cells(), phi);
  find_max(sf);
  return sf;
}

std::optional<std::string> overfull_cell_reason(const Grid& grid, const SolidsFraction& sf,
                                                double d, bool centroid) {
  if (sf.max < 1.0) return std::nullopt;
  const std::size_t nx = std::size_t(grid.n[0]), ny = std::size_t(grid.n[1]);
  const std::array<int, 3> x{int(sf.argmax % nx), int(sf.argmax / nx % ny), int(sf.argmax / nx / ny)};
  char buf[512];
  if (centroid) {
    std::snprintf(buf, sizeof buf,
                  "centroid deposition puts solids fraction eps_s = %.3g in cell (%d,%d,%d): "
                  "the cell (delta* = %.3g) is too small for grid-coupled deposition, which fails "
                  "below delta* of about 1 (no gas left in the cell); use diffusion deposition",
                  sf.max, x[0], x[1], x[2], grid.delta_star(d));
  } else {
    std::snprintf(buf, sizeof buf,
                  "solids fraction eps_s = %.3g >= 1 in cell (%d,%d,%d) after deposition: "
                  "no gas left in the cell; use a wider filter",
                  sf.max, x[0], x[1], x[2]);
  }
  return std::string(buf);
}

}  // namespace gridfree
