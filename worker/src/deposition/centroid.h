// SPDX-License-Identifier: GPL-3.0-or-later
// Centroid (grid-coupled) deposition (PHYSICS.md §3.1): each particle's
// quantity goes to the cell containing its centre, divided by V_c.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "grid/grid.h"
#include "particles/particle.h"

namespace gridfree {

// Cell along one axis holding coordinate x (rules in centroid.cpp).
int centroid_cell_along(const Grid& grid, int axis, double x);

// Cell index (Grid::index) holding the particle's centre.
std::size_t cell_of_particle(const Grid& grid, const Particle& p);

// Σ_{p∈c} q(p) / V_c for every cell c.
std::vector<double> deposit_centroid(const Grid& grid, const std::vector<Particle>& particles,
                                     const std::function<double(const Particle&)>& q);

// ε_s by centroid deposition of particle volume π d³/6.
std::vector<double> solids_fraction_centroid(const Grid& grid, const std::vector<Particle>& particles);

}  // namespace gridfree
