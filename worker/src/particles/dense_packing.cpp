// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/dense_packing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "particles/packing_bins.h"

namespace gridfree {
namespace {

constexpr double kCheckMargin = 1e-6;  // a pair closer than d(1 + this) is an overlap

class Region {
 public:
  explicit Region(const DensePackingRegion& r) : r_(r) {}

  Vec3 wrap_or_clamp(Vec3 x) const {
    for (int a = 0; a < 3; ++a) {
      if (r_.periodic[a]) {
        const double l = r_.length[a];
        x[a] = std::fmod(x[a], l);
        if (x[a] < 0) x[a] += l;
        if (x[a] >= l) x[a] = 0;
      } else {
        x[a] = std::clamp(x[a], r_.lo[a], r_.hi[a]);
      }
    }
    return x;
  }

  // Out of any hole (radially), then into the bounds; where a hole meets a
  // bound, out of the hole along the bound's plane (the clamped axes kept).
  Vec3 project(Vec3 x, const CellList& cells) const {
    if (untouched_by_projection(x, cells)) return x;
    for (int pass = 0; pass < 3; ++pass) {
      std::array<bool, 3> free{true, true, true};
      for (const Vec3& h : r_.holes) x = push_out(x, h, free, cells);
      x = wrap_or_clamp(x);
      if (allowed(x, cells)) return x;
      for (int a = 0; a < 3; ++a)
        free[a] = r_.periodic[a] || (x[a] > r_.lo[a] && x[a] < r_.hi[a]);
      for (const Vec3& h : r_.holes) x = push_out(x, h, free, cells);
      x = wrap_or_clamp(x);
      if (allowed(x, cells)) return x;
    }
    return x;  // still inside: later sweeps move it again
  }

  // True when project(x) is x itself: inside the bounds, on a periodic axis
  // in [0, L), and outside every hole by push_out's own test (so no hole
  // moves x, wrap_or_clamp leaves it, and allowed(x) holds).
  bool untouched_by_projection(const Vec3& x, const CellList& cells) const {
    for (int a = 0; a < 3; ++a) {
      if (r_.periodic[a] ? !(x[a] >= 0 && x[a] < r_.length[a]) : !(x[a] >= r_.lo[a] && x[a] <= r_.hi[a])) return false;
    }
    const double rr = r_.hole_radius * (1 + 1e-12);
    return std::none_of(r_.holes.begin(), r_.holes.end(),
                        [&](const Vec3& h) { return cells.distance_squared(h, x) < rr * rr; });
  }

  bool allowed(const Vec3& x, const CellList& cells) const {
    for (int a = 0; a < 3; ++a)
      if (!r_.periodic[a] && (x[a] < r_.lo[a] || x[a] > r_.hi[a])) return false;
    const double rr = r_.hole_radius;
    return std::none_of(r_.holes.begin(), r_.holes.end(),
                        [&](const Vec3& h) { return cells.distance_squared(h, x) < rr * rr; });
  }

  // Moves x out of the hole centred at h along the free axes only.
  Vec3 push_out(Vec3 x, const Vec3& h, const std::array<bool, 3>& free, const CellList& cells) const {
    const double rr = r_.hole_radius * (1 + 1e-12);
    const Vec3 s = cells.separation(h, x);
    double fixed2 = 0, free2 = 0;
    for (int a = 0; a < 3; ++a) (free[a] ? free2 : fixed2) += s[a] * s[a];
    if (fixed2 + free2 >= rr * rr) return x;
    const double want = std::sqrt(std::max(0.0, rr * rr - fixed2));
    if (free2 == 0) {
      for (int a = 0; a < 3; ++a)
        if (free[a]) {
          x[a] = h[a] + (a == 1 ? want : -want);  // any free direction: up, or −x / −z
          return x;
        }
      return x;
    }
    const double f = want / std::sqrt(free2);
    for (int a = 0; a < 3; ++a)
      if (free[a]) x[a] = h[a] + s[a] * f;
    return x;
  }

  double lo(int a) const { return r_.periodic[a] ? 0.0 : r_.lo[a]; }
  double hi(int a) const { return r_.periodic[a] ? r_.length[a] : r_.hi[a]; }

 private:
  const DensePackingRegion& r_;
};

}  // namespace

std::vector<Vec3> random_dense_packing(const DensePackingRegion& region, double diameter, std::size_t n,
                                       ParticleRandom& rng, const DensePackingOptions& options,
                                       DensePackingTrace* trace) {
  std::vector<Vec3> x = random_packing_centres(region, diameter, n, rng);
  remove_overlaps(region, diameter, x, rng, options, trace);
  return x;
}

std::vector<Vec3> random_packing_centres(const DensePackingRegion& region, double diameter, std::size_t n,
                                         ParticleRandom& rng) {
  const Region allowed(region);
  const CellList cells(region.length, region.periodic, diameter * (1 + 1e-3));

  // 1. Uniform centres in the allowed set.
  std::vector<Vec3> x;
  x.reserve(n);
  for (std::size_t tries = 0; x.size() < n; ++tries) {
    if (tries > 1000 * (n + 1000)) throw std::runtime_error("no room for the centres outside the holes");
    Vec3 c{};
    for (int a = 0; a < 3; ++a) c[a] = rng.uniform(allowed.lo(a), allowed.hi(a));
    if (!allowed.allowed(c, cells)) continue;
    x.push_back(c);
  }
  // In slabs of one diameter (y, then z, then x), so that the sweeps walk
  // through memory and space together (5× faster at 90 000 particles).
  const auto key = [&](const Vec3& c) {
    return std::array<double, 5>{std::floor(c[1] / diameter), std::floor(c[2] / diameter), c[0], c[1], c[2]};
  };
  std::sort(x.begin(), x.end(), [&](const Vec3& a, const Vec3& b) { return key(a) < key(b); });
  return x;
}

void remove_overlaps(const DensePackingRegion& region, double diameter, std::vector<Vec3>& x, ParticleRandom& rng,
                     const DensePackingOptions& options, DensePackingTrace* trace) {
  const Region allowed(region);
  const CellList cells(region.length, region.periodic, diameter * (1 + 1e-3));
  const std::size_t n = x.size();
  // The bins the centres (inside lo..hi on bounded axes) and their
  // neighbour bins can reach.
  PackingBins::Bin bin_lo{}, bin_hi{};
  {
    Vec3 at_lo{}, at_hi{};
    for (int a = 0; a < 3; ++a) {
      at_lo[a] = allowed.lo(a);
      at_hi[a] = region.periodic[a] ? 0.0 : allowed.hi(a);
    }
    const auto c_lo = cells.bin_of(at_lo), c_hi = cells.bin_of(at_hi);
    for (int a = 0; a < 3; ++a) {
      const int n_a = cells.bins_per_axis()[a];
      bin_lo[a] = region.periodic[a] ? 0 : std::max(0, c_lo[a] - 1);
      bin_hi[a] = region.periodic[a] ? n_a - 1 : std::min(n_a - 1, c_hi[a] + 1);
    }
  }
  PackingBins bins(cells, bin_lo, bin_hi);
  std::vector<PackingBins::Bin> home_bin(n);
  std::vector<std::size_t> home_slot(n);
  for (std::size_t i = 0; i < x.size(); ++i) {
    home_bin[i] = cells.bin_of(x[i]);
    home_slot[i] = bins.slot(home_bin[i]);
    bins.insert(static_cast<std::uint32_t>(i), home_slot[i], x[i]);
  }

  // 2–3. Gauss–Seidel overlap removal while δ grows to d.
  //
  // Visits that cannot move anything are skipped (exactly: the packing is
  // the same bit for bit). Once δ = d, the test "closer than d(1 + 10⁻⁶)"
  // no longer changes between sweeps, so a particle whose visit moved
  // nothing moves nothing on its next visit either, unless a particle in
  // the bins around it has moved since. Every move stamps the mover's old
  // and new bin with a counter; a particle is visited again only if a bin
  // around it has a stamp newer than its last visit that moved nothing
  // (clean_at; 0 = no such visit). Measured on the SSCP-sized bed, this
  // skips about a quarter of the visits, most of them in the last sweeps.
  std::vector<std::uint64_t> changed(bins.slots(), 0);
  std::vector<std::uint64_t> clean_at(n, 0);
  std::uint64_t stamp = 1;
  double delta = std::min(1.0, options.start_fraction) * diameter;
  std::vector<std::uint32_t> near;
  std::vector<Vec3> near_x;
  // A centre well inside its bin's interval on every axis (by 10⁻⁹ of a
  // bin) is in that bin: floor(x / h) cannot round across the bin's edge.
  const Vec3& h = cells.bin_size();
  const auto bin_after_move = [&](const PackingBins::Bin& from, const Vec3& to) {
    for (int a = 0; a < 3; ++a) {
      const double edge = from[a] * h[a], margin = 1e-9 * h[a];
      if (!(to[a] > edge + margin && to[a] < edge + h[a] - margin)) return cells.bin_of(to);
    }
    return from;
  };
  const auto move_to = [&](std::uint32_t id, const Vec3& to) {
    const PackingBins::Bin to_bin = bin_after_move(home_bin[id], to);
    const std::size_t from_slot = home_slot[id], to_slot = bins.slot(to_bin);
    changed[from_slot] = changed[to_slot] = ++stamp;
    if (to_slot != from_slot) {
      bins.remove(id, from_slot);
      bins.insert(id, to_slot, to);
      home_bin[id] = to_bin;
      home_slot[id] = to_slot;
    } else {
      bins.update(id, from_slot, to);
    }
    x[id] = to;
  };
  const auto untouched_since = [&](const PackingBins::Bin& home, std::uint64_t t) {
    bool quiet = true;
    bins.for_each_around(home, [&](std::size_t s) { quiet = quiet && changed[s] <= t; });
    return quiet;
  };
  for (int sweep = 1; sweep <= options.max_sweeps; ++sweep) {
    const bool full = delta >= diameter;
    const double check = full ? diameter * (1 + kCheckMargin) : delta;
    const double push = delta * (1 + std::max(options.push_margin, 2 * kCheckMargin));
    std::size_t moves = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (full && clean_at[i] != 0 && untouched_since(home_bin[i], clean_at[i])) continue;
      const std::size_t moves_before = moves;
      if (!allowed.allowed(x[i], cells)) {
        move_to(i, allowed.project(x[i], cells));
        ++moves;
      }
      // The neighbours' ids and centres; a neighbour moves during this
      // visit only when its own pair is pushed, so the copy of a centre
      // not yet reached is the centre.
      near.clear();
      near_x.clear();
      bins.for_each_around(home_bin[i], [&](std::size_t s) {
        bins.for_each_in(s, [&](std::uint32_t j, const Vec3& c) {
          if (j != i) {
            near.push_back(j);
            near_x.push_back(c);
          }
        });
      });
      for (std::size_t q = 0; q < near.size(); ++q) {
        const std::uint32_t j = near[q];
        Vec3 s = cells.separation(x[i], near_x[q]);
        double d2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
        if (d2 >= check * check) continue;
        if (d2 < 1e-24 * diameter * diameter) {  // coincident: any direction
          s = {rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5};
          d2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
          for (double& v : s) v *= 1e-9 * diameter / std::sqrt(d2);
          d2 = 1e-18 * diameter * diameter;
        }
        // Half the gap each; what a bound or hole takes from i's share goes to j.
        const double dist = std::sqrt(d2);
        const Vec3 u{s[0] / dist, s[1] / dist, s[2] / dist};
        const double need = (push - dist) * options.over_relaxation;
        const Vec3 to_i = allowed.project(
            {x[i][0] - 0.5 * need * u[0], x[i][1] - 0.5 * need * u[1], x[i][2] - 0.5 * need * u[2]}, cells);
        const Vec3 moved = cells.separation(to_i, x[i]);
        const double rest = need - std::max(0.0, moved[0] * u[0] + moved[1] * u[1] + moved[2] * u[2]);
        move_to(i, to_i);
        move_to(j, allowed.project({x[j][0] + rest * u[0], x[j][1] + rest * u[1], x[j][2] + rest * u[2]}, cells));
        ++moves;
      }
      clean_at[i] = full && moves == moves_before ? stamp : 0;
    }
    if (full && moves == 0) {
      const bool inside = std::all_of(x.begin(), x.end(), [&](const Vec3& c) { return allowed.allowed(c, cells); });
      if (inside) {
        if (trace != nullptr) trace->sweeps = sweep;
        return;
      }
    }
    delta = std::min(diameter, delta * (1 + options.growth));
  }
  throw std::runtime_error("overlaps remain after the last sweep");
}

}  // namespace gridfree
