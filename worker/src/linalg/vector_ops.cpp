// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/vector_ops.h"
#include "linalg/parallel_threshold.h"

#include <cmath>

namespace gridfree {

namespace {

// Fixed-order reduction: f(begin, end) sums one block; blocks are combined
// in order, so the thread count never changes the result.
template <class BlockSum>
double reduce_blocks(std::size_t n, BlockSum f) {
  const std::size_t blocks = (n + kReductionBlock - 1) / kReductionBlock;
  if (blocks <= 1) return n ? f(std::size_t(0), n) : 0.0;
  std::vector<double> partial(blocks);
  const long long nb = static_cast<long long>(blocks);
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (long long b = 0; b < nb; ++b) {
    const std::size_t begin = std::size_t(b) * kReductionBlock;
    const std::size_t end = begin + kReductionBlock < n ? begin + kReductionBlock : n;
    partial[std::size_t(b)] = f(begin, end);
  }
  double total = 0;
  for (double p : partial) total += p;
  return total;
}

}  // namespace

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  const double* x = a.data();
  const double* y = b.data();
  return reduce_blocks(a.size(), [x, y](std::size_t begin, std::size_t end) {
    double s = 0;
    for (std::size_t i = begin; i < end; ++i) s += x[i] * y[i];
    return s;
  });
}

double norm2(const std::vector<double>& a) { return std::sqrt(dot(a, a)); }

double sum(const std::vector<double>& a) {
  const double* x = a.data();
  return reduce_blocks(a.size(), [x](std::size_t begin, std::size_t end) {
    double s = 0;
    for (std::size_t i = begin; i < end; ++i) s += x[i];
    return s;
  });
}

void remove_mean(std::vector<double>& a) {
  if (a.empty()) return;
  const double mean = sum(a) / static_cast<double>(a.size());
  const std::size_t n = a.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) a[i] -= mean;
}

void axpy(double alpha, const std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = y.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) y[i] += alpha * x[i];
}

void xpby(const std::vector<double>& x, double beta, std::vector<double>& y) {
  const std::size_t n = y.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + beta * y[i];
}

double cg_update(double alpha, const std::vector<double>& p, const std::vector<double>& q,
                 std::vector<double>& x, std::vector<double>& r) {
  const double* pp = p.data();
  const double* qq = q.data();
  double* xx = x.data();
  double* rr = r.data();
  return reduce_blocks(x.size(), [=](std::size_t begin, std::size_t end) {
    double s = 0;
    for (std::size_t i = begin; i < end; ++i) {
      xx[i] += alpha * pp[i];
      rr[i] -= alpha * qq[i];
      s += rr[i] * rr[i];
    }
    return s;
  });
}

bool all_finite(const std::vector<double>& a) {
  const double* x = a.data();
  const double bad = reduce_blocks(a.size(), [x](std::size_t begin, std::size_t end) {
    double s = 0;
    for (std::size_t i = begin; i < end; ++i) s += std::isfinite(x[i]) ? 0.0 : 1.0;
    return s;
  });
  return bad == 0;
}

}  // namespace gridfree
