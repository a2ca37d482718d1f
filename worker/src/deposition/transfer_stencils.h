// SPDX-License-Identifier: GPL-3.0-or-later
// Per-particle transfer stencils: which cells a particle's kernel touches and
// with what weight (docs/PHYSICS.md §3, docs/TRANSFER.md). Built once for a
// frozen bed; used both ways, so deposition and sampling are exact adjoints:
//
//   deposit:  q_c = Σ_p q_p W_p(c) / V_c          (Σ_c q_c V_c = Σ_p q_p, as Σ_c W_p(c) = 1)
//   sample:   φ(x_p) = Σ_c W_p(c) φ_c
//
// so Σ_c V_c q_c φ_c = Σ_p q_p φ(x_p) exactly (up to the round-off of the
// sums). W_p(c) = w_x(i) w_y(j) w_z(k), the folded 1-D weights of
// kernel_weights.h. The deposition is a serial loop in particle order, so the
// result does not depend on the thread count.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "grid/grid.h"
#include "particles/particle.h"

namespace gridfree {

// The pre-deposition kernel (docs/TRANSFER.md).
enum class PreDeposition { kCentroid, kTrilinear, kGaussian };

std::string_view pre_deposition_name(PreDeposition k);

// The gas values a particle's drag sees (docs/TRANSFER.md):
//   cell       ε_g and the cell-centre gas velocity of the particle's cell;
//   trilinear  Σ_c W_p(c) φ_c with the trilinear weights, the gas velocity
//              first passed through the deposition's filter (the adjoint of
//              deposit-then-filter: the interphase forces then balance);
//   gaussian   the same with the gaussian kernel's weights (no filter).
enum class Sampling { kCell, kTrilinear, kGaussian };

std::string_view sampling_name(Sampling s);

struct KernelParams {
  PreDeposition kind = PreDeposition::kTrilinear;
  double sigma = 0;               // cm, gaussian only: the target σ = δ_f / √(8 ln 2)
  double truncation_sigmas = 4;   // gaussian only: weights beyond mσ are dropped, the rest renormalised
};

// Average variance the kernel adds per axis, as a multiple of Δ_i² (centroid
// 1/12, trilinear 1/6) — the uniform sub-cell average; gaussian returns 0
// (its variance is σ² by construction and no filter follows).
double kernel_variance_per_h2(PreDeposition kind);

class TransferStencils {
 public:
  TransferStencils(const Grid& grid, const std::vector<Particle>& particles, const KernelParams& params);

  // q_c = Σ_p q[p] W_p(c) / V_c into `out` (resized to the cell count).
  void deposit(const std::vector<double>& q, std::vector<double>& out) const;
  // Σ_c W_p(c) field[c].
  double sample(std::size_t p, const std::vector<double>& field) const;
  std::size_t size() const { return count_.size(); }
  // Σ_c W_p(c) over the grid (1 to round-off; for tests).
  double total_weight(std::size_t p) const;

 private:
  template <class F>
  void for_each_cell(std::size_t p, F&& f) const;
  Grid grid_;
  std::vector<std::array<std::uint32_t, 3>> offset_;  // start of each axis' weights in the pools
  std::vector<std::array<std::uint32_t, 3>> count_;
  std::vector<int> cell_;
  std::vector<double> weight_;
};

}  // namespace gridfree
