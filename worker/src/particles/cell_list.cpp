// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/cell_list.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

CellList::CellList(const Vec3& length, const std::array<bool, 3>& periodic, double min_cell,
                   std::size_t max_bins)
    : length_(length), periodic_(periodic) {
  double cell = std::max(min_cell, 1e-300);
  for (;;) {
    std::size_t total = 1;
    for (int a = 0; a < 3; ++a) {
      n_[a] = static_cast<int>(std::clamp(std::floor(length_[a] / cell), 1.0, 1e6));
      total *= static_cast<std::size_t>(n_[a]);
    }
    if (total <= max_bins) break;
    cell *= 1.25;
  }
  for (int a = 0; a < 3; ++a) h_[a] = length_[a] / n_[a];
  bins_.resize(std::size_t(n_[0]) * n_[1] * n_[2]);
}

std::array<int, 3> CellList::bin_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a) {
    double x = p[a];
    if (periodic_[a] && (x < 0 || x >= length_[a])) {
      x = std::fmod(x, length_[a]);
      if (x < 0) x += length_[a];
    }
    c[a] = std::clamp(static_cast<int>(std::floor(x / h_[a])), 0, n_[a] - 1);
  }
  return c;
}

void CellList::insert(std::uint32_t id, const Vec3& p) {
  const auto c = bin_of(p);
  bins_[flat(c[0], c[1], c[2])].push_back(id);
}

void CellList::remove(std::uint32_t id, const Vec3& p) {
  const auto c = bin_of(p);
  auto& bin = bins_[flat(c[0], c[1], c[2])];
  if (auto it = std::find(bin.begin(), bin.end(), id); it != bin.end()) {
    *it = bin.back();
    bin.pop_back();
  }
}

void CellList::move(std::uint32_t id, const Vec3& from, const Vec3& to) {
  if (bin_of(from) == bin_of(to)) return;
  remove(id, from);
  insert(id, to);
}

}  // namespace gridfree
