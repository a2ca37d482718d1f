// SPDX-License-Identifier: GPL-3.0-or-later
// Structure statistics of a bed of spheres (docs/PARTICLES.md "Structure"):
// whether it is a lattice or a random packing, and how ε_s varies.
//
// - Structure factor S(k) = |Σ_j exp(i k·x_j)|² / N on the axis-aligned wave
//   vectors the box allows, k = 2π m / L_a (m = 1, 2, ...), for periods
//   L_a / m between min_period_dp and max_period_dp diameters (0.5 d and
//   2 d by default: the scales of packing order; on a non-periodic axis a
//   longer wave sees the bed's own extent, e.g. a slab of height H gives
//   S ≈ N sinc²(kH/2), which is order N at kH ≲ π). A random packing has
//   S of order 1 (S/N → 0); a crystal has S of order N at its layer
//   spacing (S/N = 1 for a perfect one). Measured twice: over all
//   particles, and over the core, the particles at least min(3 d, extent/4)
//   inside every non-periodic side of the particles' bounding box, with the
//   core window's own transform (N times the mean of exp(ikx) over x
//   uniform in the window) subtracted so its edges do not leak. Walls layer
//   a packed bed over a few diameters (random or not), and on a thin wall
//   axis those layers are a large share of the particles: sscp_like's
//   random emulsion between walls 8 d apart gives S/N ≈ 0.12 along that
//   axis over all particles.
// - g(r) for r ≤ 3 d in bins of 0.02 d: pairs whose first particle lies at
//   least 3 d inside every non-periodic side of the particles' bounding
//   box, normalised by that core's mean number density. Its features: the
//   contact peak (the largest g, at r < 1.1 d), and the values at √3 d,
//   2 d and the smallest g between them (the split second peak of a random
//   dense packing has two maxima there; a crystal has sharp peaks at √2 d,
//   √3 d, 2 d).
// - ε_s(y): exact sphere–slab volumes in bins of one diameter, over the
//   domain's cross-section.
// - Local ε_s: cubes of side ≈ 3 d tiling the domain up to the top of the
//   highest sphere, each particle's volume given to the cube holding its
//   centre; histogram in bins of 0.02 and the mean and standard deviation.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "particles/particle.h"

namespace gridfree {

struct StructurePeak {
  int axis = 0;           // 0 x, 1 y, 2 z
  int m = 0;              // k = 2π m / L
  double period_dp = 0;   // L / m, in diameters
  double s_over_n = 0;    // S(k) / N
};

struct RadialDistribution {
  double bin_dp = 0.02;
  std::vector<double> g;  // g[i] at r = (i + 1/2) bin, in diameters
  std::size_t reference_particles = 0;
  double contact_peak = 0, contact_peak_r_dp = 0;  // max g for r < 1.1 d
  double at_sqrt3 = 0, at_2 = 0, dip_between = 0;  // g(√3 d), g(2 d), min g in between
};

struct BedStructure {
  std::size_t particles = 0;
  double diameter_cm = 0;
  std::array<StructurePeak, 3> largest_peak_per_axis{};
  StructurePeak largest_peak{};
  std::size_t core_particles = 0;
  std::array<StructurePeak, 3> largest_core_peak_per_axis{};
  StructurePeak largest_core_peak{};
  RadialDistribution rdf;
  std::vector<double> solids_fraction_y;  // per slab of one diameter, from y = 0
  double local_cube_dp = 3;
  std::vector<std::size_t> local_histogram;  // bins of 0.02 in ε_s, from 0
  double local_mean = 0, local_std = 0;
  std::size_t local_cubes = 0;
};

struct StructureOptions {
  double min_period_dp = 0.5;
  double max_period_dp = 2.0;
};

// A window [lo, hi] whose uniform-density transform is subtracted on
// non-periodic axes.
struct PeakWindow {
  std::array<bool, 3> periodic{};
  std::array<double, 3> lo{}, hi{};
};

// Largest S(k)/N per axis over the allowed periods (particles of one
// diameter d; positions in cm inside the box [0, L)).
std::array<StructurePeak, 3> largest_structure_peaks(const std::vector<Particle>& particles,
                                                     const std::array<double, 3>& length_cm, double d,
                                                     const StructureOptions& options = {},
                                                     const PeakWindow* window = nullptr);
RadialDistribution radial_distribution(const std::vector<Particle>& particles, const std::array<double, 3>& length_cm,
                                       const std::array<bool, 3>& periodic, double d);
std::vector<double> solids_fraction_profile_y(const std::vector<Particle>& particles,
                                              const std::array<double, 3>& length_cm, double d);

// All of the above; d = the first particle's diameter (equal spheres).
BedStructure bed_structure(const std::vector<Particle>& particles, const std::array<double, 3>& length_cm,
                           const std::array<bool, 3>& periodic, const StructureOptions& options = {});

nlohmann::json to_json(const BedStructure& s);
std::string to_text(const BedStructure& s);

}  // namespace gridfree
