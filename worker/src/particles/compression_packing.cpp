// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/compression_packing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace gridfree {
namespace {

// Region and centres in units of the diameter d.
struct UnitRegion {
  Vec3 length{};
  std::array<bool, 3> periodic{};
  Vec3 lo{}, hi{};
  std::vector<Vec3> holes;
  double hole_radius = 0;
};

Vec3 min_image(const UnitRegion& r, const Vec3& a, const Vec3& b) {
  Vec3 s{};
  for (int k = 0; k < 3; ++k) {
    s[k] = b[k] - a[k];
    if (r.periodic[k]) s[k] -= r.length[k] * std::round(s[k] / r.length[k]);
  }
  return s;
}

// Pairs closer than `cut`, by counting sort of the centres into bins ≥ cut.
class PairList {
 public:
  PairList(const UnitRegion& r, double cut) : r_(r) {
    for (int a = 0; a < 3; ++a) {
      n_[a] = std::max(1, static_cast<int>(std::floor(r.length[a] / cut)));
      h_[a] = r.length[a] / n_[a];
    }
    start_.resize(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1);
  }

  void build(const std::vector<Vec3>& x, double cut) {
    const std::size_t nb = start_.size() - 1;
    std::vector<std::uint32_t> bin(x.size());
    std::fill(start_.begin(), start_.end(), 0);
    for (std::size_t i = 0; i < x.size(); ++i) {
      bin[i] = static_cast<std::uint32_t>(flat(coords(x[i])));
      ++start_[bin[i] + 1];
    }
    for (std::size_t b = 0; b < nb; ++b) start_[b + 1] += start_[b];
    members_.resize(x.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < x.size(); ++i) members_[fill[bin[i]]++] = static_cast<std::uint32_t>(i);
    pairs_.clear();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const auto c = coords(x[i]);
      std::array<std::array<int, 3>, 3> idx{};
      std::array<int, 3> count{};
      for (int a = 0; a < 3; ++a)
        for (int o = -1; o <= 1; ++o) {
          int b = c[a] + o;
          if (r_.periodic[a]) b = (b % n_[a] + n_[a]) % n_[a];
          else if (b < 0 || b >= n_[a]) continue;
          if (std::find(idx[a].begin(), idx[a].begin() + count[a], b) == idx[a].begin() + count[a])
            idx[a][count[a]++] = b;
        }
      for (int k = 0; k < count[2]; ++k)
        for (int j = 0; j < count[1]; ++j)
          for (int q = 0; q < count[0]; ++q) {
            const std::size_t b = flat({idx[0][q], idx[1][j], idx[2][k]});
            for (std::uint32_t m = start_[b]; m < start_[b + 1]; ++m) {
              const std::uint32_t o = members_[m];
              if (o <= i) continue;
              const Vec3 s = min_image(r_, x[i], x[o]);
              if (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] < cut * cut)
                pairs_.emplace_back(static_cast<std::uint32_t>(i), o);
            }
          }
    }
  }

  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs() const { return pairs_; }

 private:
  std::array<int, 3> coords(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) {
      double v = p[a];
      if (r_.periodic[a]) v -= r_.length[a] * std::floor(v / r_.length[a]);
      c[a] = std::clamp(static_cast<int>(std::floor(v / h_[a])), 0, n_[a] - 1);
    }
    return c;
  }
  std::size_t flat(const std::array<int, 3>& c) const {
    return (static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
  }

  const UnitRegion& r_;
  std::array<int, 3> n_{};
  Vec3 h_{};
  std::vector<std::uint32_t> start_, members_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
};

// Forces −∇E for spheres of diameter sigma (unit spring); returns the
// largest overlap (pair, bound or hole).
double overlap_forces(const UnitRegion& r, const std::vector<Vec3>& x, double sigma, const PairList& list,
                      std::vector<Vec3>& f) {
  std::fill(f.begin(), f.end(), Vec3{});
  double worst = 0;
  for (const auto& [i, j] : list.pairs()) {
    const Vec3 s = min_image(r, x[i], x[j]);
    const double d2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    if (d2 >= sigma * sigma) continue;
    const double d = std::sqrt(d2);
    const double ov = sigma - d;
    worst = std::max(worst, ov);
    const double k = d > 0 ? ov / d : 0;
    for (int a = 0; a < 3; ++a) {
      f[i][a] -= k * s[a];
      f[j][a] += k * s[a];
    }
  }
  const double grow_out = 0.5 * (1 - sigma);  // bounds and holes move out by (d − σ)/2
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      if (r.periodic[a]) continue;
      const double lo = r.lo[a] - grow_out, hi = r.hi[a] + grow_out;
      if (x[i][a] < lo) {
        f[i][a] += lo - x[i][a];
        worst = std::max(worst, lo - x[i][a]);
      } else if (x[i][a] > hi) {
        f[i][a] -= x[i][a] - hi;
        worst = std::max(worst, x[i][a] - hi);
      }
    }
    const double hole = r.hole_radius - grow_out;
    for (const Vec3& h : r.holes) {
      const Vec3 s = min_image(r, h, x[i]);
      const double d2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
      if (d2 >= hole * hole || d2 == 0) continue;
      const double d = std::sqrt(d2), ov = hole - d;
      worst = std::max(worst, ov);
      for (int a = 0; a < 3; ++a) f[i][a] += ov * s[a] / d;
    }
  }
  return worst;
}

}  // namespace

std::vector<Vec3> compressed_dense_packing(const DensePackingRegion& region, double diameter, std::size_t n,
                                           ParticleRandom& rng, const CompressionOptions& options,
                                           CompressionTrace* trace) {
  std::vector<Vec3> x = random_packing_centres(region, diameter, n, rng);
  UnitRegion r;
  for (int a = 0; a < 3; ++a) {
    r.length[a] = region.length[a] / diameter;
    r.periodic[a] = region.periodic[a];
    r.lo[a] = region.lo[a] / diameter;
    r.hi[a] = region.hi[a] / diameter;
  }
  for (const Vec3& h : region.holes) r.holes.push_back({h[0] / diameter, h[1] / diameter, h[2] / diameter});
  r.hole_radius = region.hole_radius / diameter;
  for (Vec3& c : x)
    for (double& v : c) v /= diameter;

  constexpr double kSkin = 0.3;
  PairList list(r, 1 + kSkin);
  std::vector<Vec3> v(n), f(n), at_build = x;
  double sigma = std::min(1.0, options.start_fraction), sigma_at_build = sigma;
  list.build(x, sigma + kSkin);
  long steps = 0;
  int stages = 0;
  for (;;) {
    ++stages;
    const bool last = sigma >= 1;
    const double tol = (last ? options.final_tolerance : options.tolerance) * sigma;
    double dt = 0.05, alpha = 0.1;
    int positive = 0;
    std::fill(v.begin(), v.end(), Vec3{});
    for (;;) {
      // The list holds every pair closer than σ while no two centres have
      // closed in by more than the skin left after σ's growth.
      double moved = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 s = min_image(r, at_build[i], x[i]);
        moved = std::max(moved, s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      }
      if (2 * std::sqrt(moved) + (sigma - sigma_at_build) >= kSkin) {
        list.build(x, sigma + kSkin);
        at_build = x;
        sigma_at_build = sigma;
      }
      const double worst = overlap_forces(r, x, sigma, list, f);
      if (worst < tol) break;
      if (++steps > options.max_steps) throw std::runtime_error("the compression did not converge");
      // FIRE: mix the velocity towards the force while power is positive.
      double power = 0, vv = 0, ff = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
          power += f[i][a] * v[i][a];
          vv += v[i][a] * v[i][a];
          ff += f[i][a] * f[i][a];
        }
      if (power > 0) {
        const double mix = ff > 0 ? alpha * std::sqrt(vv / ff) : 0;
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < 3; ++a) v[i][a] = (1 - alpha) * v[i][a] + mix * f[i][a];
        if (++positive > 5) {
          dt = std::min(1.1 * dt, 0.2);
          alpha *= 0.99;
        }
      } else {
        std::fill(v.begin(), v.end(), Vec3{});
        dt *= 0.5;
        alpha = 0.1;
        positive = 0;
      }
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
          v[i][a] += dt * f[i][a];
          x[i][a] += dt * v[i][a];
          if (r.periodic[a]) x[i][a] -= r.length[a] * std::floor(x[i][a] / r.length[a]);
        }
    }
    if (last) break;
    sigma = sigma * (1 + options.growth) >= 1 ? 1 + options.final_margin : sigma * (1 + options.growth);
  }

  for (Vec3& c : x)
    for (double& val : c) val *= diameter;
  DensePackingTrace sweeps;
  remove_overlaps(region, diameter, x, rng, {}, &sweeps);
  if (trace != nullptr) *trace = {stages, steps, sweeps.sweeps};
  return x;
}

}  // namespace gridfree
