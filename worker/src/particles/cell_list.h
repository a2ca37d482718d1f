// SPDX-License-Identifier: GPL-3.0-or-later
// A hashing grid ("cell list") for neighbour queries among particles in a box
// with optional periodic axes, so overlap checks cost O(1) per particle and
// O(N) in all.
//
// The box [0,L₀]×[0,L₁]×[0,L₂] is cut into n_a = max(1, ⌊L_a / h⌋) bins per
// axis with h ≥ the largest contact distance, so any two particles in
// contact sit in the same or adjacent bins (wrapping on periodic axes).
// Distances use the minimum image on periodic axes: Δ ← Δ − L·round(Δ/L).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridfree {

using Vec3 = std::array<double, 3>;

class CellList {
 public:
  // `min_cell` = the largest contact distance (e.g. the particle diameter).
  // The bin count is capped near `max_bins` (bins grow instead) so a big,
  // sparse domain does not allocate a huge grid.
  CellList(const Vec3& length, const std::array<bool, 3>& periodic, double min_cell,
           std::size_t max_bins = std::size_t(1) << 23);

  void insert(std::uint32_t id, const Vec3& p);
  void remove(std::uint32_t id, const Vec3& p);  // p = where it was inserted
  void move(std::uint32_t id, const Vec3& from, const Vec3& to);

  // Calls f(id) for every stored id in the bins around p (each bin once).
  template <class F>
  void for_each_near(const Vec3& p, F&& f) const {
    for_each_bin_around(bin_of(p), [&](const std::array<int, 3>& c) {
      for (std::uint32_t id : bins_[flat(c[0], c[1], c[2])]) f(id);
    });
  }

  // The geometry alone, for a caller that keeps its own bins on it (the
  // dense packing, particles/packing_bins.h): the bin of p, the bins per
  // axis, and f(c') for the bins c' around bin c (c itself included, each
  // once) in the order for_each_near visits them. c' is around c exactly
  // when c is around c'.
  std::array<int, 3> bin_of(const Vec3& p) const;
  const std::array<int, 3>& bins_per_axis() const { return n_; }
  const Vec3& bin_size() const { return h_; }
  template <class F>
  void for_each_bin_around(const std::array<int, 3>& c, F&& f) const {
    std::array<std::array<int, 3>, 3> idx{};
    std::array<int, 3> count{};
    for (int a = 0; a < 3; ++a) {
      for (int o = -1; o <= 1; ++o) {
        int b = c[a] + o;
        if (periodic_[a]) b = (b % n_[a] + n_[a]) % n_[a];
        else if (b < 0 || b >= n_[a]) continue;
        bool seen = false;
        for (int q = 0; q < count[a]; ++q) seen = seen || idx[a][q] == b;
        if (!seen) idx[a][count[a]++] = b;
      }
    }
    for (int k = 0; k < count[2]; ++k)
      for (int j = 0; j < count[1]; ++j)
        for (int i = 0; i < count[0]; ++i) f(std::array<int, 3>{idx[0][i], idx[1][j], idx[2][k]});
  }

  // Minimum-image separation b − a (inline: the hot path of every overlap test).
  Vec3 separation(const Vec3& a, const Vec3& b) const {
    Vec3 s{};
    for (int i = 0; i < 3; ++i) {
      s[i] = b[i] - a[i];
      if (periodic_[i]) {
        // The branches cover |s| <= 1.5 L (wrapped centres, query points
        // near the box); std::round takes the rest.
        const double l = length_[i];
        if (s[i] > 0.5 * l) s[i] -= l;
        else if (s[i] < -0.5 * l) s[i] += l;
        if (s[i] > 0.5 * l || s[i] < -0.5 * l) s[i] -= l * std::round(s[i] / l);
      }
    }
    return s;
  }
  double distance_squared(const Vec3& a, const Vec3& b) const {
    const Vec3 s = separation(a, b);
    return s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
  }

  const Vec3& length() const { return length_; }
  const std::array<bool, 3>& periodic() const { return periodic_; }

 private:
  std::size_t flat(int i, int j, int k) const { return (std::size_t(k) * n_[1] + j) * n_[0] + i; }

  Vec3 length_;
  std::array<bool, 3> periodic_;
  std::array<int, 3> n_{1, 1, 1};
  Vec3 h_{};
  std::vector<std::vector<std::uint32_t>> bins_;
};

}  // namespace gridfree
