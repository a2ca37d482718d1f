// SPDX-License-Identifier: GPL-3.0-or-later
// Non-overlapping placement of equal spheres in a box (the machinery behind
// the generators): a cell list for O(1) overlap tests, centre bounds that
// keep spheres off non-periodic walls, and random sequential addition (RSA).
//
// Overlap: |c_i − c_j|_min-image < d. Centre bounds per axis: [0, L) when
// periodic, [r, L − r] otherwise (r = d/2; y is never periodic, so spheres
// never cross the inflow/outflow planes).
// RSA draws candidate centres uniformly from a region and keeps those that
// overlap nothing. Near saturation almost every candidate fails, so after a
// streak of failures it switches to sampling voxels (side ≈ d/2) of the
// region and drops each voxel found to lie wholly inside some sphere's
// exclusion zone (every corner closer than d to one centre; the zone is
// convex). Candidates stay uniform over the space not yet excluded, so the
// process is still exact RSA, and it ends when no voxel is left (jammed).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "particles/cell_list.h"
#include "particles/random.h"

namespace gridfree {

// An axis-aligned box [lo, hi) of candidate centres.
struct Box {
  Vec3 lo{}, hi{};
};

class SpherePacker {
 public:
  SpherePacker(const Vec3& length, const std::array<bool, 3>& periodic, double diameter);

  double diameter() const { return d_; }
  const Vec3& length() const { return cells_.length(); }
  bool periodic(int axis) const { return cells_.periodic()[axis]; }
  // Allowed centre interval on an axis (see header comment).
  double lo(int axis) const { return periodic(axis) ? 0.0 : 0.5 * d_; }
  double hi(int axis) const { return periodic(axis) ? length()[axis] : length()[axis] - 0.5 * d_; }
  bool within_bounds(const Vec3& c) const;
  // Wraps periodic coordinates into [0, L).
  Vec3 wrap(Vec3 c) const;

  // True when a sphere at c overlaps no stored sphere (except `ignore`).
  bool fits(const Vec3& c, std::uint32_t ignore = UINT32_MAX) const;
  std::uint32_t add(const Vec3& c);
  void move(std::uint32_t id, const Vec3& to);
  const std::vector<Vec3>& centres() const { return centres_; }
  const CellList& cells() const { return cells_; }

  // Random sequential addition of up to `count` spheres with centres
  // uniform in `box` ∩ {x : in_region(x)} ∩ the centre bounds. Returns how
  // many were placed: fewer than `count` only when the region is jammed
  // (no room left for a centre) or `max_failures` candidates in a row fail.
  std::size_t add_random(std::size_t count, ParticleRandom& rng, const Box& box,
                         const std::function<bool(const Vec3&)>& in_region,
                         std::size_t max_failures = 20000000);

 private:
  double d_;
  CellList cells_;
  std::vector<Vec3> centres_;
};

}  // namespace gridfree
