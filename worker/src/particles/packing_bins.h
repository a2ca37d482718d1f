// SPDX-License-Identifier: GPL-3.0-or-later
// The dense packing's bins (particles/dense_packing.h): the particles of
// each bin of a CellList's geometry, id and a copy of the centre, stored
// flat, over the box of bins lo..hi (per axis, inclusive) that the
// particles and their neighbour bins can reach, instead of one heap vector
// of ids per bin of the whole domain. A sweep then reads a neighbourhood's
// centres from a few nearly contiguous blocks.
//
// The ids of a bin keep CellList's order exactly: an entering id is
// appended, a leaving id's place is taken by the bin's last. So visiting the
// bins of CellList::for_each_bin_around in turn visits the ids in the order
// CellList::for_each_near would, and the packing stays the same bit for bit.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "particles/cell_list.h"

namespace gridfree {

class PackingBins {
 public:
  using Bin = std::array<int, 3>;

  PackingBins(const CellList& cells, const Bin& lo, const Bin& hi) : cells_(cells), lo_(lo) {
    const Bin& n = cells.bins_per_axis();
    for (int a = 0; a < 3; ++a) {
      m_[a] = static_cast<std::size_t>(hi[a] - lo[a] + 1);
      inner_lo_[a] = std::max(1, lo[a] + 1);
      inner_hi_[a] = std::min(n[a] - 2, hi[a] - 1);
    }
    blocks_.resize(m_[0] * m_[1] * m_[2]);
    spill_.resize(blocks_.size());
  }

  // The storage index of bin c (lo <= c <= hi): y-major, so that a sweep in
  // y slabs reads the blocks nearly in order.
  std::size_t slot(const Bin& c) const {
    return (static_cast<std::size_t>(c[1] - lo_[1]) * m_[2] + static_cast<std::size_t>(c[2] - lo_[2])) * m_[0] +
           static_cast<std::size_t>(c[0] - lo_[0]);
  }
  std::size_t slots() const { return blocks_.size(); }

  void insert(std::uint32_t id, std::size_t s, const Vec3& x) {
    Block& b = blocks_[s];
    if (b.count < kInline) {
      b.ids[b.count] = id;
      b.centres[b.count] = x;
    } else {
      spill_[s].push_back({id, x});
    }
    ++b.count;
  }

  void remove(std::uint32_t id, std::size_t s) {
    Block& b = blocks_[s];
    for (std::uint32_t k = 0; k < b.count; ++k) {
      if (id_at(s, k) != id) continue;
      const std::uint32_t last = b.count - 1;
      set_at(s, k, id_at(s, last), centre_at(s, last));
      if (last >= kInline) spill_[s].pop_back();
      --b.count;
      return;
    }
  }

  void update(std::uint32_t id, std::size_t s, const Vec3& x) {
    for (std::uint32_t k = 0; k < blocks_[s].count; ++k)
      if (id_at(s, k) == id) {
        set_at(s, k, id, x);
        return;
      }
  }

  // f(id, centre) for the particles in storage slot s, in bin order.
  template <class F>
  void for_each_in(std::size_t s, F&& f) const {
    const Block& b = blocks_[s];
    const std::uint32_t inline_count = std::min(b.count, kInline);
    for (std::uint32_t k = 0; k < inline_count; ++k) f(b.ids[k], b.centres[k]);
    if (b.count > kInline)
      for (const Entry& e : spill_[s]) f(e.id, e.centre);
  }

  // f(slot) for the bins around bin c in CellList::for_each_bin_around's
  // order (z, then y, then x); away from bounds and wraps that is the
  // order of the offsets.
  template <class F>
  void for_each_around(const Bin& c, F&& f) const {
    bool inner = true;
    for (int a = 0; a < 3; ++a) inner = inner && c[a] >= inner_lo_[a] && c[a] <= inner_hi_[a];
    if (!inner) {
      cells_.for_each_bin_around(c, [&](const Bin& b) { f(slot(b)); });
      return;
    }
    const std::size_t s = slot(c), dz = m_[0], dy = m_[0] * m_[2];
    for (std::size_t k = s - dz; k <= s + dz; k += dz)
      for (std::size_t j = k - dy; j <= k + dy; j += dy)
        for (std::size_t i = j - 1; i <= j + 1; ++i) f(i);
  }

 private:
  // Three particles a bin in the block (one centre per d³ at ε_s ≈ 0.6),
  // the rest in the bin's spill list.
  static constexpr std::uint32_t kInline = 3;
  struct Block {
    std::uint32_t count = 0;
    std::array<std::uint32_t, kInline> ids{};
    std::array<Vec3, kInline> centres{};
  };
  struct Entry {
    std::uint32_t id;
    Vec3 centre;
  };

  std::uint32_t id_at(std::size_t s, std::uint32_t k) const {
    return k < kInline ? blocks_[s].ids[k] : spill_[s][k - kInline].id;
  }
  const Vec3& centre_at(std::size_t s, std::uint32_t k) const {
    return k < kInline ? blocks_[s].centres[k] : spill_[s][k - kInline].centre;
  }
  void set_at(std::size_t s, std::uint32_t k, std::uint32_t id, const Vec3& x) {
    if (k < kInline) {
      blocks_[s].ids[k] = id;
      blocks_[s].centres[k] = x;
    } else {
      spill_[s][k - kInline] = {id, x};
    }
  }

  const CellList& cells_;
  Bin lo_;
  std::array<std::size_t, 3> m_{};
  Bin inner_lo_{}, inner_hi_{};  // bins whose neighbours are c ± 1 on every axis, inside lo..hi
  std::vector<Block> blocks_;
  std::vector<std::vector<Entry>> spill_;  // per slot: the particles after the first kInline
};

}  // namespace gridfree
