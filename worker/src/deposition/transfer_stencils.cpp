// SPDX-License-Identifier: GPL-3.0-or-later
// Per-particle stencils from the 1-D kernels (transfer_stencils.h).
// Non-periodic coordinates are clamped into [0, L] first (a centre on the
// wall deposits like one just inside it).
#include "deposition/transfer_stencils.h"

#include <algorithm>
#include <stdexcept>

#include "deposition/centroid.h"
#include "deposition/kernel_weights.h"

namespace gridfree {

std::string_view pre_deposition_name(PreDeposition k) {
  switch (k) {
    case PreDeposition::kCentroid: return "centroid";
    case PreDeposition::kTrilinear: return "trilinear";
    case PreDeposition::kGaussian: return "gaussian";
  }
  return "?";
}

std::string_view sampling_name(Sampling s) {
  switch (s) {
    case Sampling::kCell: return "cell";
    case Sampling::kTrilinear: return "trilinear";
    case Sampling::kGaussian: return "gaussian";
  }
  return "?";
}

double kernel_variance_per_h2(PreDeposition kind) {
  switch (kind) {
    case PreDeposition::kCentroid: return 1.0 / 12.0;
    case PreDeposition::kTrilinear: return 1.0 / 6.0;
    case PreDeposition::kGaussian: return 0.0;
  }
  return 0.0;
}

namespace {

AxisWeights axis_weights(const Grid& g, int axis, double x, const KernelParams& k) {
  if (k.kind == PreDeposition::kCentroid) return {{centroid_cell_along(g, axis, x)}, {1.0}};
  if (!g.periodic[axis]) x = std::clamp(x, 0.0, g.length[axis]);
  const AxisWeights raw = k.kind == PreDeposition::kTrilinear
                              ? trilinear_weights(x, g.h(axis))
                              : gaussian_weights(x, g.h(axis), k.sigma, k.truncation_sigmas);
  return fold_axis_weights(raw, g.n[axis], g.periodic[axis]);
}

}  // namespace

TransferStencils::TransferStencils(const Grid& grid, const std::vector<Particle>& particles,
                                   const KernelParams& params)
    : grid_(grid) {
  if (params.kind == PreDeposition::kGaussian && !(params.sigma > 0 && params.truncation_sigmas > 0))
    throw std::invalid_argument("gaussian kernel needs sigma > 0 and truncation_sigmas > 0");
  offset_.resize(particles.size());
  count_.resize(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const std::array<double, 3> x{particles[p].x, particles[p].y, particles[p].z};
    for (int a = 0; a < 3; ++a) {
      const AxisWeights w = axis_weights(grid_, a, x[std::size_t(a)], params);
      offset_[p][std::size_t(a)] = static_cast<std::uint32_t>(cell_.size());
      count_[p][std::size_t(a)] = static_cast<std::uint32_t>(w.cell.size());
      cell_.insert(cell_.end(), w.cell.begin(), w.cell.end());
      weight_.insert(weight_.end(), w.weight.begin(), w.weight.end());
    }
  }
}

template <class F>
void TransferStencils::for_each_cell(std::size_t p, F&& f) const {
  const auto& o = offset_[p];
  const auto& n = count_[p];
  for (std::uint32_t mk = 0; mk < n[2]; ++mk) {
    const int k = cell_[o[2] + mk];
    const double wz = weight_[o[2] + mk];
    for (std::uint32_t mj = 0; mj < n[1]; ++mj) {
      const int j = cell_[o[1] + mj];
      const double wyz = weight_[o[1] + mj] * wz;
      for (std::uint32_t mi = 0; mi < n[0]; ++mi)
        f(grid_.index(cell_[o[0] + mi], j, k), weight_[o[0] + mi] * wyz);
    }
  }
}

void TransferStencils::deposit(const std::vector<double>& q, std::vector<double>& out) const {
  out.assign(grid_.cells(), 0.0);
  for (std::size_t p = 0; p < count_.size(); ++p) {
    const double qp = q[p];
    for_each_cell(p, [&](std::size_t c, double w) { out[c] += qp * w; });
  }
  const double inv_volume = 1.0 / grid_.cell_volume();
  for (double& v : out) v *= inv_volume;
}

double TransferStencils::sample(std::size_t p, const std::vector<double>& field) const {
  double s = 0;
  for_each_cell(p, [&](std::size_t c, double w) { s += w * field[c]; });
  return s;
}

double TransferStencils::total_weight(std::size_t p) const {
  double s = 0;
  for_each_cell(p, [&](std::size_t, double w) { s += w; });
  return s;
}

}  // namespace gridfree
