// SPDX-License-Identifier: GPL-3.0-or-later
// Independent checks for generated configurations, deliberately simple:
// an O(N²) loop over all pairs with the nearest periodic image found by
// trying the shifts −L, 0, +L on every periodic axis (no cell list, no
// rounding tricks shared with the code under test).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "particles/particle.h"

namespace gridfree::test {

// Number of pairs closer than (1 − 1e-12)(r_i + r_j). The 1e-12 relative
// slack absorbs rounding in the distance itself (the generators guarantee
// distance >= d computed in the same arithmetic; a genuine overlap is a
// finite fraction of d).
inline std::size_t count_overlaps(const std::vector<Particle>& ps, const std::array<double, 3>& length,
                                  const std::array<bool, 3>& periodic) {
  std::size_t overlaps = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      const double contact = 0.5 * (ps[i].d + ps[j].d) * (1 - 1e-12);
      const double delta[3] = {ps[i].x - ps[j].x, ps[i].y - ps[j].y, ps[i].z - ps[j].z};
      double best = 0;
      for (int a = 0; a < 3; ++a) {
        double m = std::abs(delta[a]);
        if (periodic[a]) m = std::min({m, std::abs(delta[a] - length[a]), std::abs(delta[a] + length[a])});
        best += m * m;
      }
      if (best < contact * contact) ++overlaps;
    }
  }
  return overlaps;
}

// Particles whose centre lies outside [0, L] (or within r of a wall).
inline std::size_t count_outside(const std::vector<Particle>& ps, const std::array<double, 3>& length,
                                 const std::array<bool, 3>& periodic) {
  std::size_t outside = 0;
  for (const Particle& p : ps) {
    const double c[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      const double margin = periodic[a] ? 0.0 : 0.5 * p.d;
      if (c[a] < margin || c[a] > length[a] - margin || (periodic[a] && c[a] >= length[a])) {
        ++outside;
        break;
      }
    }
  }
  return outside;
}

}  // namespace gridfree::test
