// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/sphere_packer.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

SpherePacker::SpherePacker(const Vec3& length, const std::array<bool, 3>& periodic, double diameter)
    : d_(diameter), cells_(length, periodic, diameter) {}

bool SpherePacker::within_bounds(const Vec3& c) const {
  for (int a = 0; a < 3; ++a)
    if (!periodic(a) && (c[a] < lo(a) || c[a] > hi(a))) return false;
  return true;
}

Vec3 SpherePacker::wrap(Vec3 c) const {
  for (int a = 0; a < 3; ++a) {
    if (!periodic(a)) continue;
    const double l = length()[a];
    c[a] = std::fmod(c[a], l);
    if (c[a] < 0) c[a] += l;
    if (c[a] >= l) c[a] = 0;  // fmod of a tiny negative number can round up to l
  }
  return c;
}

bool SpherePacker::fits(const Vec3& c, std::uint32_t ignore) const {
  const double d2 = d_ * d_;
  bool ok = true;
  cells_.for_each_near(c, [&](std::uint32_t id) {
    if (ok && id != ignore && cells_.distance_squared(c, centres_[id]) < d2) ok = false;
  });
  return ok;
}

std::uint32_t SpherePacker::add(const Vec3& c) {
  const auto id = static_cast<std::uint32_t>(centres_.size());
  centres_.push_back(c);
  cells_.insert(id, c);
  return id;
}

void SpherePacker::move(std::uint32_t id, const Vec3& to) {
  cells_.move(id, centres_[id], to);
  centres_[id] = to;
}

}  // namespace gridfree

namespace gridfree {
namespace {

constexpr std::size_t kPlainStreak = 5000;        // failures in a row before voxels
constexpr std::size_t kMaxVoxels = std::size_t(1) << 23;
constexpr int kMaxSplits = 6;  // voxel side down to d/256

}  // namespace

std::size_t SpherePacker::add_random(std::size_t count, ParticleRandom& rng, const Box& box,
                                     const std::function<bool(const Vec3&)>& in_region, std::size_t max_failures) {
  Box b = box;
  for (int a = 0; a < 3; ++a) {
    if (periodic(a)) continue;
    b.lo[a] = std::max(b.lo[a], lo(a));
    b.hi[a] = std::min(b.hi[a], hi(a));
  }
  for (int a = 0; a < 3; ++a)
    if (!(b.lo[a] < b.hi[a])) return 0;

  const auto try_at = [&](const Vec3& candidate) {
    if (!in_region(candidate)) return false;
    const Vec3 c = wrap(candidate);
    if (!fits(c)) return false;
    add(c);
    return true;
  };

  // Plain RSA while it works.
  std::size_t placed = 0, failures = 0;
  while (placed < count && failures < kPlainStreak) {
    const Vec3 c{rng.uniform(b.lo[0], b.hi[0]), rng.uniform(b.lo[1], b.hi[1]), rng.uniform(b.lo[2], b.hi[2])};
    if (try_at(c)) {
      ++placed;
      failures = 0;
    } else {
      ++failures;
    }
  }
  if (placed == count) return placed;

  // Voxel RSA: uniform over the voxels not yet known to be excluded. A voxel
  // is dropped when one sphere's exclusion zone holds all its corners; when
  // candidates keep failing (voxels partly covered by several spheres),
  // every voxel is split in eight and the test repeated, so the sampled
  // volume shrinks towards the truly available one (the voxel method of
  // Zhang & Torquato, Phys. Rev. E 88, 053312, 2013).
  double side = 0.5 * d_;
  std::array<int, 3> n{};
  for (;;) {
    std::size_t total = 1;
    for (int a = 0; a < 3; ++a) {
      n[a] = std::max(1, static_cast<int>(std::ceil((b.hi[a] - b.lo[a]) / side)));
      total *= static_cast<std::size_t>(n[a]);
    }
    if (total <= kMaxVoxels) break;
    side *= 1.25;
  }
  Vec3 h{(b.hi[0] - b.lo[0]) / n[0], (b.hi[1] - b.lo[1]) / n[1], (b.hi[2] - b.lo[2]) / n[2]};
  const double d2 = d_ * d_;
  const auto excluded = [&](const Vec3& o) {
    const Vec3 mid{o[0] + 0.5 * h[0], o[1] + 0.5 * h[1], o[2] + 0.5 * h[2]};
    const double half_diagonal = 0.5 * std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    const double sure = std::max(0.0, d_ - half_diagonal);
    bool covered = false;
    cells_.for_each_near(wrap(mid), [&](std::uint32_t id) {
      if (covered) return;
      // Quick answers from the centre: too far to cover it, or so close that
      // the whole voxel is inside; the corners decide the rest.
      const double m2 = cells_.distance_squared(mid, centres_[id]);
      if (m2 >= d2) return;
      if (m2 < sure * sure) {
        covered = true;
        return;
      }
      bool all = true;
      for (int q = 0; q < 8 && all; ++q) {
        const Vec3 x{o[0] + (q & 1) * h[0], o[1] + ((q >> 1) & 1) * h[1], o[2] + ((q >> 2) & 1) * h[2]};
        all = cells_.distance_squared(x, centres_[id]) < d2;
      }
      covered = all;
    });
    return covered;
  };
  std::vector<Vec3> active;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Vec3 o{b.lo[0] + i * h[0], b.lo[1] + j * h[1], b.lo[2] + k * h[2]};
        if (!excluded(o)) active.push_back(o);
      }

  failures = 0;
  std::size_t since_split = 0;
  int splits = 0;
  while (placed < count && !active.empty() && failures < max_failures) {
    if (since_split > 4 * active.size() + 1000 && splits < kMaxSplits && active.size() * 8 <= kMaxVoxels) {
      for (int a = 0; a < 3; ++a) h[a] *= 0.5;
      std::vector<Vec3> finer;
      for (const Vec3& o : active)
        for (int q = 0; q < 8; ++q) {
          const Vec3 child{o[0] + (q & 1) * h[0], o[1] + ((q >> 1) & 1) * h[1], o[2] + ((q >> 2) & 1) * h[2]};
          if (!excluded(child)) finer.push_back(child);
        }
      active.swap(finer);
      since_split = 0;
      ++splits;
      continue;
    }
    const std::size_t slot = rng.below(active.size());
    const Vec3 o = active[slot];
    const Vec3 c{o[0] + h[0] * rng.uniform(), o[1] + h[1] * rng.uniform(), o[2] + h[2] * rng.uniform()};
    if (try_at(c)) {
      ++placed;
      failures = 0;
    } else {
      ++failures;
      ++since_split;
      if (excluded(o)) {
        active[slot] = active.back();
        active.pop_back();
      }
    }
  }
  return placed;
}

}  // namespace gridfree
