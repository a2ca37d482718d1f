// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic parallel reductions.
//
// An OpenMP `reduction(+:...)` adds partial sums in an order that depends on
// the thread count, so results would change at round-off with --threads.
// Here the range is cut into fixed blocks (independent of the thread count),
// each block is summed in order by one thread, and the block sums are added
// serially: the same bits for any number of threads.
#pragma once

#include <cstddef>
#include <vector>

namespace gridfree {

inline constexpr std::size_t kReductionBlock = 4096;
// Loops shorter than this run on one thread (thread start-up would dominate).
inline constexpr long kMinParallel = 16384;

// Σ_{i<n} term(i), bitwise independent of the thread count.
template <class Term>
double deterministic_sum(std::size_t n, const Term& term) {
  const std::size_t blocks = (n + kReductionBlock - 1) / kReductionBlock;
  std::vector<double> partial(blocks, 0.0);
#pragma omp parallel for schedule(static) if (blocks > 4)
  for (long b = 0; b < static_cast<long>(blocks); ++b) {
    const std::size_t lo = std::size_t(b) * kReductionBlock;
    const std::size_t hi = lo + kReductionBlock < n ? lo + kReductionBlock : n;
    double s = 0.0;
    for (std::size_t i = lo; i < hi; ++i) s += term(i);
    partial[std::size_t(b)] = s;
  }
  double total = 0.0;
  for (double s : partial) total += s;
  return total;
}

}  // namespace gridfree
