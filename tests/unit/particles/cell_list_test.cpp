// SPDX-License-Identifier: GPL-3.0-or-later
// The cell list finds every neighbour a brute-force search finds, also on
// periodic axes with only one or two bins (each bin visited once).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "particles/cell_list.h"
#include "particles/random.h"

namespace gridfree {
namespace {

// Brute force over images −L, 0, +L on periodic axes.
double image_distance(const Vec3& a, const Vec3& b, const Vec3& length, const std::array<bool, 3>& periodic) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    double m = std::abs(a[i] - b[i]);
    if (periodic[i]) m = std::min({m, std::abs(a[i] - b[i] - length[i]), std::abs(a[i] - b[i] + length[i])});
    sum += m * m;
  }
  return std::sqrt(sum);
}

TEST(CellList, MatchesBruteForce) {
  const double reach = 1.0;
  const std::array<Vec3, 3> boxes = {Vec3{10, 7, 5}, Vec3{1.5, 6, 2.5}, Vec3{3.2, 3.2, 3.2}};
  for (const Vec3& length : boxes) {
    for (const std::array<bool, 3> periodic : {std::array<bool, 3>{true, false, true}, std::array<bool, 3>{false, false, false}}) {
      ParticleRandom rng(3);
      std::vector<Vec3> points(300);
      CellList cells(length, periodic, reach);
      for (std::uint32_t i = 0; i < points.size(); ++i) {
        points[i] = {rng.uniform(0, length[0]), rng.uniform(0, length[1]), rng.uniform(0, length[2])};
        cells.insert(i, points[i]);
      }
      for (std::uint32_t i = 0; i < points.size(); ++i) {
        std::multiset<std::uint32_t> seen;
        cells.for_each_near(points[i], [&](std::uint32_t j) { seen.insert(j); });
        for (std::uint32_t j = 0; j < points.size(); ++j) {
          const double d = image_distance(points[i], points[j], length, periodic);
          if (d < reach) {
            ASSERT_EQ(seen.count(j), 1u) << "point " << i << " misses " << j;
          }
          // The minimum-image distance agrees with brute force (1e-12 for rounding).
          ASSERT_NEAR(std::sqrt(cells.distance_squared(points[i], points[j])), d, 1e-12);
        }
        for (std::uint32_t j : seen) ASSERT_EQ(seen.count(j), 1u);  // no bin visited twice
      }
    }
  }
}

TEST(CellList, MoveAndRemove) {
  CellList cells({4, 4, 4}, {false, false, false}, 1.0);
  cells.insert(0, {0.5, 0.5, 0.5});
  cells.move(0, {0.5, 0.5, 0.5}, {3.5, 3.5, 3.5});
  int found = 0;
  cells.for_each_near({0.5, 0.5, 0.5}, [&](std::uint32_t) { ++found; });
  EXPECT_EQ(found, 0);
  cells.for_each_near({3.2, 3.4, 3.9}, [&](std::uint32_t) { ++found; });
  EXPECT_EQ(found, 1);
  cells.remove(0, {3.5, 3.5, 3.5});
  cells.for_each_near({3.2, 3.4, 3.9}, [&](std::uint32_t) { ++found; });
  EXPECT_EQ(found, 1);
}

}  // namespace
}  // namespace gridfree
