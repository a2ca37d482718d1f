// SPDX-License-Identifier: GPL-3.0-or-later
// ε_s from particles: centroid deposition, optional Gaussian filter (see header).
#include "coupling/solids_fraction.h"

#include <cmath>
#include <cstdio>
#include <numbers>

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
  s.kernel_variance_per_h2 = kernel_variance_per_h2(deposition.pre_deposition);
  s.integration = deposition.integration;
  s.steps = deposition.steps;
  s.tolerance = tolerance;
  return s;
}

KernelParams kernel_params(const DepositionSpec& deposition, double d) {
  KernelParams k;
  k.kind = deposition.kind == DepositionKind::kCentroid ? PreDeposition::kCentroid : deposition.pre_deposition;
  k.sigma = deposition.fwhm_dp * d / std::sqrt(8.0 * std::numbers::ln2);
  k.truncation_sigmas = deposition.truncation_sigmas;
  return k;
}

bool is_filtered(const DepositionSpec& deposition) {
  return deposition.kind == DepositionKind::kDiffusion && deposition.pre_deposition != PreDeposition::kGaussian;
}

SolidsFraction deposit_solids_fraction(const Grid& grid, const std::vector<Particle>& particles,
                                       const DepositionSpec& deposition, double d,
                                       double filter_tolerance) {
  SolidsFraction sf;
  const KernelParams kernel = kernel_params(deposition, d);
  if (kernel.kind == PreDeposition::kCentroid) {
    sf.eps_s = solids_fraction_centroid(grid, particles);
  } else {
    std::vector<double> volume(particles.size());
    for (std::size_t p = 0; p < particles.size(); ++p)
      volume[p] = std::numbers::pi / 6.0 * particles[p].d * particles[p].d * particles[p].d;
    TransferStencils(grid, particles, kernel).deposit(volume, sf.eps_s);
  }
  if (is_filtered(deposition)) {
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
