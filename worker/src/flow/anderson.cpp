// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/anderson.h"

#include <Eigen/Dense>

#include <cmath>

#include "flow/parallel.h"

namespace gridfree {
namespace {

double dot_weighted(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& w) {
  return deterministic_sum(a.size(), [&](std::size_t i) { return w[i] * a[i] * b[i]; });
}

}  // namespace

void AndersonMixer::pack(const FaceVector& u, const std::vector<double>& p, std::vector<double>& out) {
  out.clear();
  for (int a = 0; a < 3; ++a) out.insert(out.end(), u[a].values.begin(), u[a].values.end());
  out.insert(out.end(), p.begin(), p.end());
}

void AndersonMixer::reset() {
  last_f_.clear();
  last_g_.clear();
  delta_f_.clear();
  delta_g_.clear();
}

void AndersonMixer::mix(const std::vector<double>& x, FaceVector& u, std::vector<double>& p) {
  std::vector<double> g;
  pack(u, p, g);
  const std::size_t n = g.size();
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = g[i] - x[i];

  // Block weights 1 / RMS(G) squared (the norm is weighted by W²).
  std::vector<double> w(n);
  std::size_t start = 0;
  for (int blk = 0; blk < 4; ++blk) {
    const std::size_t len = blk < 3 ? u[blk].size() : p.size();
    const double ms = deterministic_sum(len, [&](std::size_t i) { return g[start + i] * g[start + i]; }) /
                      static_cast<double>(std::max<std::size_t>(1, len));
    const double weight = ms > 0 ? 1.0 / ms : 0.0;
    for (std::size_t i = 0; i < len; ++i) w[start + i] = weight;
    start += len;
  }

  if (!last_f_.empty()) {
    std::vector<double> df(n), dg(n);
    for (std::size_t i = 0; i < n; ++i) {
      df[i] = f[i] - last_f_[i];
      dg[i] = g[i] - last_g_[i];
    }
    delta_f_.push_back(std::move(df));
    delta_g_.push_back(std::move(dg));
    if (static_cast<int>(delta_f_.size()) > depth_) {
      delta_f_.pop_front();
      delta_g_.pop_front();
    }
  }
  last_f_ = f;
  last_g_ = g;
  const int m = static_cast<int>(delta_f_.size());
  if (m == 0) return;

  Eigen::MatrixXd A(m, m);
  Eigen::VectorXd rhs(m);
  for (int i = 0; i < m; ++i) {
    rhs(i) = dot_weighted(delta_f_[std::size_t(i)], f, w);
    for (int j = 0; j <= i; ++j) A(i, j) = A(j, i) = dot_weighted(delta_f_[std::size_t(i)], delta_f_[std::size_t(j)], w);
  }
  const double trace = A.trace();
  if (!(trace > 0) || !std::isfinite(trace)) return;
  A += 1e-10 * trace * Eigen::MatrixXd::Identity(m, m);
  const Eigen::VectorXd gamma = A.ldlt().solve(rhs);
  if (!gamma.allFinite()) return;

  for (int j = 0; j < m; ++j) {
    const std::vector<double>& dg = delta_g_[std::size_t(j)];
    for (std::size_t i = 0; i < n; ++i) g[i] -= gamma(j) * dg[i];
  }
  std::size_t off = 0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t i = 0; i < u[a].size(); ++i) u[a][i] = g[off++];
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = g[off++];
}

}  // namespace gridfree
