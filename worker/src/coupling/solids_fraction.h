// SPDX-License-Identifier: GPL-3.0-or-later
// Solids volume fraction on the grid (PHYSICS.md §3).
//
//   centroid:   ε_s(c) = Σ_{p ∈ c} V_p / V_c                 (grid-coupled)
//   diffusion:  ε_s(c) = Σ_p V_p W_p(c) / V_c with the pre-deposition kernel
//               W (centroid, trilinear, gaussian; transfer_stencils.h), then
//               filtered by apply_filter, ∂α/∂τ = ν ∇²α, FWHM δ_f = fwhm_dp · d
//               (grid-independent); the gaussian kernel is not filtered
//   uniform:    ε_s = φ in every cell                        (continuum bed)
//
// Centroid deposition on cells smaller than a particle (Δ* ≲ 1) puts
// ε_s ≥ 1 in some cells: centroid_failure() turns that into a reason.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "deposition/filter.h"
#include "deposition/transfer_stencils.h"
#include "grid/grid.h"
#include "job/job_spec.h"
#include "particles/particle.h"

namespace gridfree {

struct SolidsFraction {
  std::vector<double> eps_s;
  double max = 0;            // max ε_s over the cells
  std::size_t argmax = 0;    // a cell holding it
  bool filtered = false;
  FilterStats filter;        // when filtered
};

// The filter settings of a diffusion deposition for particle diameter d (cm).
FilterSettings filter_settings(const DepositionSpec& deposition, double d, double tolerance);

// The pre-deposition kernel of a deposition for particle diameter d (cm):
// centroid for kind "centroid"; σ = δ_f/√(8 ln 2) for the gaussian kernel.
KernelParams kernel_params(const DepositionSpec& deposition, double d);

// True when a diffusion filter follows the pre-deposition.
bool is_filtered(const DepositionSpec& deposition);

// ε_s by the job's deposition kind.
SolidsFraction deposit_solids_fraction(const Grid& grid, const std::vector<Particle>& particles,
                                       const DepositionSpec& deposition, double d,
                                       double filter_tolerance);

SolidsFraction uniform_solids_fraction(const Grid& grid, double phi);

// A reason when some cell has ε_s ≥ 1 (no gas left), else nullopt.
std::optional<std::string> overfull_cell_reason(const Grid& grid, const SolidsFraction& sf,
                                                double d, bool centroid);

}  // namespace gridfree
