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
    for_each_bin_around(bin_of(p), [&](std::size_t b) {
      for (std::uint32_t id : bins_[b]) f(id);
    });
  }

  // Bins by flat index, for callers that keep each particle's bin (the
  // dense packing): the bin of p, the ids in bin b in the order
  // for_each_near visits them, and f(b') for the bins around bin b (b
  // itself included, each once) in for_each_near's order. Bin b' is around
  // b exactly when b is around b'.
  std::size_t bin_index(const Vec3& p) const {
    const auto c = bin_of(p);
    return flat(c[0], c[1], c[2]);
  }
  std::size_t bin_count() const { return bins_.size(); }
  const std::vector<std::uint32_t>& bin(std::size_t b) const { return bins_[b]; }
  template <class F>
  void for_each_bin_around(std::size_t b, F&& f) const {
    const auto nx = static_cast<std::size_t>(n_[0]), ny = static_cast<std::size_t>(n_[1]);
    const std::array<int, 3> c{static_cast<int>(b % nx), static_cast<int>(b / nx % ny),
                               static_cast<int>(b / (nx * ny))};
    bool inner = true;
    for (int a = 0; a < 3; ++a) inner = inner && c[a] >= 1 && c[a] + 1 < n_[a];
    if (!inner) {
      for_each_bin_around(c, f);
      return;
    }
    // No bound or wrap near b: the general order, k then j then i, is
    // that of the flat offsets.
    for (std::size_t k = b - nx * ny; k <= b + nx * ny; k += nx * ny)
      for (std::size_t j = k - nx; j <= k + nx; j += nx)
        for (std::size_t i = j - 1; i <= j + 1; ++i) f(i);
  }
  // move() for a caller that knows both bins (from = the bin id is in).
  void move_between_bins(std::uint32_t id, std::size_t from, std::size_t to);

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
        for (int i = 0; i < count[0]; ++i) f(flat(idx[0][i], idx[1][j], idx[2][k]));
  }
  std::array<int, 3> bin_of(const Vec3& p) const;
  std::size_t flat(int i, int j, int k) const { return (std::size_t(k) * n_[1] + j) * n_[0] + i; }

  Vec3 length_;
  std::array<bool, 3> periodic_;
  std::array<int, 3> n_{1, 1, 1};
  Vec3 h_{};
  std::vector<std::vector<std::uint32_t>> bins_;
};

}  // namespace gridfree
