// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/model_problems.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

namespace {

double harmonic(double a, double b) { return a + b > 0 ? 2 * a * b / (a + b) : 0.0; }

// Neighbour index along an axis, or −1 across a non-periodic boundary.
long long neighbour(const Grid& g, int i, int j, int k, int axis, int step) {
  std::array<int, 3> c{i, j, k};
  c[axis] += step;
  if (c[axis] < 0 || c[axis] >= g.n[axis]) {
    if (!g.periodic[axis]) return -1;
    c[axis] = (c[axis] + g.n[axis]) % g.n[axis];
  }
  return static_cast<long long>(g.index(c[0], c[1], c[2]));
}

// The six coefficient arrays in W, E, S, N, B, T order.
std::array<std::vector<double>*, 6> sides(Stencil7& s) {
  return {&s.aw, &s.ae, &s.as, &s.an, &s.ab, &s.at};
}

}  // namespace

Stencil7 diffusion_stencil(const Grid& g, const std::vector<double>& kappa,
                           const DirichletSides& dirichlet, double shift) {
  Stencil7 s(g);
  auto a = sides(s);
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        double ap = shift * g.cell_volume();
        for (int side = 0; side < 6; ++side) {
          const int axis = side / 2, step = side % 2 ? 1 : -1;
          const double geometric = g.face_area(axis) / g.h(axis);
          const long long nb = neighbour(g, i, j, k, axis, step);
          if (nb < 0) {
            if (dirichlet[side]) ap += 2 * kappa[c] * geometric;
            continue;
          }
          const double coefficient = harmonic(kappa[c], kappa[std::size_t(nb)]) * geometric;
          (*a[side])[c] = coefficient;
          ap += coefficient;
        }
        s.ap[c] = ap;
      }
  return s;
}

Stencil7 convection_diffusion_stencil(const Grid& g, const std::array<double, 3>& velocity,
                                      double diffusivity, const DirichletSides& dirichlet,
                                      double shift) {
  Stencil7 s(g);
  auto a = sides(s);
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        double ap = shift * g.cell_volume();
        for (int side = 0; side < 6; ++side) {
          const int axis = side / 2, step = side % 2 ? 1 : -1;
          const double d = diffusivity * g.face_area(axis) / g.h(axis);
          const double f = velocity[axis] * g.face_area(axis);
          // Upwind: the low-side neighbour feeds the cell when u > 0.
          const double coefficient = d + std::max(step < 0 ? f : -f, 0.0);
          if (neighbour(g, i, j, k, axis, step) < 0) {
            // Boundary value 0: diffusion over half a cell on a Dirichlet
            // side; inflow brings 0 in, outflow carries φ_P out.
            if (dirichlet[side]) ap += 2 * d;
            ap += std::max(step < 0 ? -f : f, 0.0);
            continue;
          }
          (*a[side])[c] = coefficient;
          ap += d + std::max(step < 0 ? -f : f, 0.0);
        }
        s.ap[c] = ap;
      }
  return s;
}

std::vector<double> bed_coefficient(const Grid& g, double contrast) {
  std::vector<double> kappa(g.cells(), 1.0);
  const double bed_top = 0.14 * g.length[1];
  const std::array<double, 3> centre{0.5 * g.length[0], 0.11 * g.length[1], 0.5 * g.length[2]};
  const double radius = g.length[0] / 6;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double x = g.centre(0, i), y = g.centre(1, j), z = g.centre(2, k);
        const double r2 = (x - centre[0]) * (x - centre[0]) + (y - centre[1]) * (y - centre[1]) +
                          (z - centre[2]) * (z - centre[2]);
        if (y < bed_top && r2 > radius * radius) kappa[g.index(i, j, k)] = 1.0 / contrast;
      }
  return kappa;
}

}  // namespace gridfree
