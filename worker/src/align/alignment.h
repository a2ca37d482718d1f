// SPDX-License-Identifier: GPL-3.0-or-later
// Grid-alignment check (docs/TRANSFER.md "Alignment check"): the part of
// the grid error that one series of grids cannot see. The job's grid is
// re-solved with the cell counts changed by a few cells and/or the particles
// shifted by a fraction of a cell, so that sharp features of the bed (its
// surface) fall at other places inside a cell; the spread of dp* over the
// variants,
//
//   spread = (max dp* − min dp*) / mean dp*   over the variants (all must converge),
//
// measures how much dp* depends on that alignment at this cell size.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flow/solve.h"

namespace gridfree {

struct AlignVariant {
  std::array<int, 3> cell_offsets{};  // added to numerics.grid.cells
  int shift_axis = 1;                 // axis of the particle shift
  double shift_fraction = 0;          // of the variant's cell size along shift_axis
};

struct AlignVariantResult {
  AlignVariant variant;
  std::array<int, 3> cells{};
  double delta_star = 0;
  SolveStatus status = SolveStatus::kFailed;
  std::string reason;
  std::optional<double> dp_star;
  int iterations = 0;
};

struct AlignReport {
  std::vector<AlignVariantResult> variants;
  // Over the variants, only when every variant converged with a dp*.
  std::optional<double> mean, min, max, spread;
  std::string reason;  // why spread is absent
};

// Every combination of the offsets and shift fractions (an empty list counts as {0}).
std::vector<AlignVariant> alignment_variants(const std::array<std::vector<int>, 3>& cell_offsets,
                                             const std::vector<double>& shift_fractions, int shift_axis);

// Particles moved by fraction·Δ along the axis (wrapped on periodic axes).
// Throws InputError (field "--shift-fractions") when a centre leaves a
// non-periodic domain.
ParticleSet shifted_particles(const ParticleSet& set, const Grid& grid, int axis, double fraction);

// Spread rule above.
void summarise_alignment(AlignReport& report);

// Solves every variant (serially) and summarises.
AlignReport run_alignment(const JobSpec& job, const ParticleSet& particles, const std::vector<AlignVariant>& variants,
                          const SolveOptions& options);

}  // namespace gridfree
