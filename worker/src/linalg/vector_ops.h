// SPDX-License-Identifier: GPL-3.0-or-later
// Vector kernels for the Krylov solvers, OpenMP-parallel and deterministic.
//
// Reductions (dot products, norms, sums) are fixed-order: the vector is cut
// into blocks of kReductionBlock entries whatever the thread count, each
// block is summed sequentially, and the block sums are added in block order.
// Results are therefore bitwise identical for any number of threads.
#pragma once

#include <cstddef>
#include <vector>

namespace gridfree {

inline constexpr std::size_t kReductionBlock = 4096;

// Σ a_i b_i.
double dot(const std::vector<double>& a, const std::vector<double>& b);
// sqrt(Σ a_i²).
double norm2(const std::vector<double>& a);
// Σ a_i.
double sum(const std::vector<double>& a);
// a_i −= mean(a).
void remove_mean(std::vector<double>& a);
// y += α x.
void axpy(double alpha, const std::vector<double>& x, std::vector<double>& y);
// y = x + β y.
void xpby(const std::vector<double>& x, double beta, std::vector<double>& y);
// x += α p; r −= α q; returns ||r||² (fixed-order) — one pass for CG.
double cg_update(double alpha, const std::vector<double>& p, const std::vector<double>& q,
                 std::vector<double>& x, std::vector<double>& r);
// True when every entry is finite.
bool all_finite(const std::vector<double>& a);

}  // namespace gridfree
