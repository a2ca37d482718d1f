// The dense packing's bins (particles/dense_packing.h): ids of particles per
// bin of a CellList's geometry, stored flat, one block per bin of a count and
// `capacity` ids (32 bytes at the start), instead of one heap vector per bin.
//
// The ids of a bin keep CellList's order exactly: an entering id is
// appended, a leaving id's place is taken by the bin's last id. So visiting
// the ids of CellList::for_each_bin_around's bins, bin after bin, visits them
// in the order CellList::for_each_near would, and the packing stays the same
// bit for bit. A bin that would overflow doubles every bin's capacity
// (the blocks are copied in order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridfree {

class PackingBins {
 public:
  explicit PackingBins(std::size_t bins, std::uint32_t capacity = 7)
      : capacity_(capacity), bins_(bins), blocks_(bins * (capacity + 1), 0) {}

  void insert(std::uint32_t id, std::size_t b) {
    if (blocks_[b * (capacity_ + 1)] == capacity_) grow();
    std::uint32_t* block = &blocks_[b * (capacity_ + 1)];
    block[1 + block[0]++] = id;
  }

  void remove(std::uint32_t id, std::size_t b) {
    std::uint32_t* block = &blocks_[b * (capacity_ + 1)];
    for (std::uint32_t k = 0; k < block[0]; ++k)
      if (block[1 + k] == id) {
        block[1 + k] = block[block[0]];
        --block[0];
        return;
      }
  }

  template <class F>
  void for_each_in(std::size_t b, F&& f) const {
    const std::uint32_t* block = &blocks_[b * (capacity_ + 1)];
    for (std::uint32_t k = 0; k < block[0]; ++k) f(block[1 + k]);
  }

 private:
  void grow() {
    const std::uint32_t wider = 2 * capacity_ + 1;
    std::vector<std::uint32_t> blocks(bins_ * (wider + 1), 0);
    for (std::size_t b = 0; b < bins_; ++b)
      for (std::uint32_t k = 0; k <= capacity_; ++k) blocks[b * (wider + 1) + k] = blocks_[b * (capacity_ + 1) + k];
    blocks_.swap(blocks);
    capacity_ = wider;
  }

  std::uint32_t capacity_;
  std::size_t bins_;
  std::vector<std::uint32_t> blocks_;  // per bin: count, then capacity_ ids
};

}  // namespace gridfree
