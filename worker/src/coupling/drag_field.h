// SPDX-License-Identifier: GPL-3.0-or-later
// The interphase drag field β (and βv̄) on the grid (PHYSICS.md §3).
//
// Particles:  f_p = D(ε_g(p), |u(p) − v_p|) V_p, then
//               β   = F( Σ_p f_p W_p / V_c ),
//               βv̄ = F( Σ_p f_p v_p W_p / V_c )   (skipped when all v_p = 0)
//             with W the pre-deposition kernel and F the same filter as ε_s
//             (none for centroid deposition or the gaussian kernel). The gas
//             values at the particle (docs/TRANSFER.md):
//               cell:      ε_g(p) = ε_g,c(p), u(p) = u_c(p), the particle's cell;
//               trilinear/gaussian:  ε_g(p) = Σ_c T_p(c) ε_g,c (T trilinear: ε_g is
//                          already filtered), u(p) = Σ_c S_p(c) F(u)_c with S the
//                          sampling kernel (trilinear or gaussian).
//
// Interphase force balance. The force on the particles is
//   F_p = Σ_p f_p (u(p) − v_p);
// the force on the gas, at cell centres with the cell-centre velocity u_c,
//   F_g = Σ_c V_c (β_c u_c − βv̄_c).
// F is symmetric in the volume-weighted inner product (uniform V_c: a
// symmetric matrix), so Σ_c V_c F(b)_c u_c = Σ_c V_c b_c F(u)_c, and with
// S = W, F_g = F_p up to round-off. interphase_force_imbalance() reports
// |F_g − F_p| / |F_p| (vector norms). The momentum equations use β averaged
// to the faces (flow/momentum.cpp); that interpolation is not part of the
// balance above, which is the cell-centre one.
// Uniform:    β = φ D(ε_g, |u_c|) per cell, no particles (Model A: β = ε_s D).
//
// The filter of β starts each step from that step's result of the previous
// update (FilterWarmStart): β changes little between outer iterations.
// f_p is computed in parallel (one slot per particle); the deposition is a
// serial loop in particle order, so β is bitwise independent of the thread count.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "deposition/filter.h"
#include "deposition/transfer_stencils.h"
#include "drag/drag_law.h"
#include "grid/grid.h"
#include "particles/particle.h"

namespace gridfree {

// Interphase momentum exchange per cell (Grid::index order): β = Σ f_p / V_c
// and βv̄ = Σ f_p v_p / V_c per component (empty when every particle is at rest).
struct DragField {
  std::vector<double> beta;
  std::array<std::vector<double>, 3> beta_v;
};

struct DragSettings {
  DragLaw law = DragLaw::kBvk;
  double d = 0;      // particle diameter, cm
  double rho_g = 0;  // g/cm³
  double mu_g = 0;   // g/(cm s)
};

// β = φ D(ε_g, |u_c|) in every cell.
void uniform_drag_field(const Grid& grid, const DragSettings& settings, double phi,
                        const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell,
                        DragField& out);

// How particle data reach the grid and back (docs/TRANSFER.md).
struct TransferSettings {
  KernelParams kernel;                 // pre-deposition kernel W
  Sampling sampling = Sampling::kCell;
  std::optional<FilterSettings> filter;  // nullopt: no filter
};

class ParticleDragField {
 public:
  // Centroid pre-deposition and cell values; `filter` = nullopt for centroid deposition.
  ParticleDragField(const Grid& grid, std::vector<Particle> particles, const DragSettings& settings,
                    std::optional<FilterSettings> filter);
  ParticleDragField(const Grid& grid, std::vector<Particle> particles, const DragSettings& settings,
                    const TransferSettings& transfer);

  void compute(const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell, DragField& out);

  const FilterStats& last_filter() const { return last_filter_; }
  int updates() const { return updates_; }
  // |F_g − F_p| / |F_p| of the last compute() (see above).
  double last_imbalance() const { return last_imbalance_; }

 private:
  Grid grid_;
  std::vector<Particle> particles_;
  std::vector<std::size_t> cell_;  // cell of each particle centre
  DragSettings settings_;
  std::optional<DiffusionFilter> filter_;  // built once: matrix and multigrid reused every update
  FilterWarmStart beta_warm_;              // β's filter steps of the last update (βv̄: cold, saves memory)
  bool moving_ = false;            // some particle has a non-zero velocity
  std::vector<double> f_;          // f_p per particle
  Sampling sampling_ = Sampling::kCell;
  std::shared_ptr<const TransferStencils> deposit_;  // null: centroid (cell_)
  std::shared_ptr<const TransferStencils> sample_;   // null: cell values; u(p)
  std::shared_ptr<const TransferStencils> eps_sample_;  // trilinear, ε_g(p) (when sample_)
  std::array<std::vector<double>, 3> u_sampled_;     // F(u_c) when sampling through the filter
  std::array<std::vector<double>, 3> force_;         // f_p (u(p) − v_p) per particle
  double last_imbalance_ = 0;
  FilterStats last_filter_;
  int updates_ = 0;
};

// |F_g − F_p| / |F_p| for a deposited field and the per-particle forces (0 when F_p = 0).
double interphase_force_imbalance(const Grid& grid, const DragField& field,
                                  const std::array<std::vector<double>, 3>& u_cell,
                                  const std::array<std::vector<double>, 3>& particle_force);

}  // namespace gridfree
