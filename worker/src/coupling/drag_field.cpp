// SPDX-License-Identifier: GPL-3.0-or-later
// Drag field from particles or a uniform bed (equations in drag_field.h).
#include "coupling/drag_field.h"

#include <cmath>
#include <numbers>

#include "deposition/centroid.h"

namespace gridfree {
namespace {

// Loops shorter than these run on one thread.
constexpr long kMinParallel = 16384;
constexpr long kMinParallelParticles = 1024;

double speed(const std::array<std::vector<double>, 3>& u, std::size_t c, double vx, double vy, double vz) {
  const double a = u[0][c] - vx, b = u[1][c] - vy, e = u[2][c] - vz;
  return std::sqrt(a * a + b * b + e * e);
}

DragState state_of(const DragSettings& s, double eps_g, double slip) {
  DragState st;
  st.eps_g = eps_g;
  st.slip = slip;
  st.d = s.d;
  st.rho_g = s.rho_g;
  st.mu_g = s.mu_g;
  return st;
}

double velocity_of(const Particle& p, int a) { return a == 0 ? p.u : (a == 1 ? p.v : p.w); }

}  // namespace

void uniform_drag_field(const Grid& grid, const DragSettings& settings, double phi,
                        const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell,
                        DragField& out) {
  out.beta.assign(grid.cells(), 0.0);
  for (auto& bv : out.beta_v) bv.clear();
  if (phi <= 0) return;
  const long cells = static_cast<long>(grid.cells());
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
  for (long cl = 0; cl < cells; ++cl) {
    const std::size_t c = std::size_t(cl);
    out.beta[c] = phi * drag_coefficient(settings.law,
                                         state_of(settings, eps_g[c], speed(u_cell, c, 0, 0, 0)));
  }
}

ParticleDragField::ParticleDragField(const Grid& grid, std::vector<Particle> particles,
                                     const DragSettings& settings, std::optional<FilterSettings> filter)
    : ParticleDragField(grid, std::move(particles), settings,
                        TransferSettings{KernelParams{PreDeposition::kCentroid, 0, 4}, Sampling::kCell, filter}) {}

ParticleDragField::ParticleDragField(const Grid& grid, std::vector<Particle> particles,
                                     const DragSettings& settings, const TransferSettings& transfer)
    : grid_(grid), particles_(std::move(particles)), settings_(settings), sampling_(transfer.sampling) {
  if (transfer.filter) filter_.emplace(grid_, *transfer.filter);
  cell_.resize(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    cell_[i] = cell_of_particle(grid_, particles_[i]);
    const Particle& p = particles_[i];
    if (p.u != 0 || p.v != 0 || p.w != 0) moving_ = true;
  }
  if (transfer.kernel.kind != PreDeposition::kCentroid)
    deposit_ = std::make_shared<TransferStencils>(grid_, particles_, transfer.kernel);
  if (sampling_ != Sampling::kCell) {
    KernelParams k = transfer.kernel;
    k.kind = sampling_ == Sampling::kTrilinear ? PreDeposition::kTrilinear : PreDeposition::kGaussian;
    sample_ = k.kind == transfer.kernel.kind ? deposit_ : std::make_shared<TransferStencils>(grid_, particles_, k);
    // ε_g is already the filtered field: it is interpolated trilinearly
    // whatever the sampling kernel (the wide kernel would smooth it twice).
    k.kind = PreDeposition::kTrilinear;
    eps_sample_ = sample_ && sampling_ == Sampling::kTrilinear
                      ? sample_
                      : (transfer.kernel.kind == PreDeposition::kTrilinear
                             ? deposit_
                             : std::make_shared<TransferStencils>(grid_, particles_, k));
  }
  f_.resize(particles_.size());
  for (auto& fp : force_) fp.resize(particles_.size());
}

void ParticleDragField::compute(const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell,
                                DragField& out) {
  const long np = static_cast<long>(particles_.size());
  // The gas velocity the particles sample: the deposition's filter applied
  // to the cell-centre velocity (the adjoint of deposit-then-filter).
  const std::array<std::vector<double>, 3>* u_seen = &u_cell;
  if (sample_ && filter_ && filter_->active()) {
    for (int a = 0; a < 3; ++a) {
      u_sampled_[a] = u_cell[a];
      filter_->apply(u_sampled_[a]);
    }
    u_seen = &u_sampled_;
  }
  // f_p = D V_p for every particle (independent: parallel).
#pragma omp parallel for schedule(static) if (np > kMinParallelParticles)
  for (long il = 0; il < np; ++il) {
    const std::size_t i = std::size_t(il);
    const Particle& p = particles_[i];
    const std::size_t c = cell_[i];
    const double vp = std::numbers::pi * p.d * p.d * p.d / 6.0;
    std::array<double, 3> slip{};
    double eps = 0;
    if (sample_) {
      eps = eps_sample_->sample(i, eps_g);
      for (int a = 0; a < 3; ++a) slip[a] = sample_->sample(i, (*u_seen)[a]) - velocity_of(p, a);
    } else {
      eps = eps_g[c];
      for (int a = 0; a < 3; ++a) slip[a] = u_cell[a][c] - velocity_of(p, a);
    }
    DragState sp = state_of(settings_, eps, sample_ ? std::sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2])
                                                    : speed(u_cell, c, p.u, p.v, p.w));
    sp.d = p.d;
    f_[i] = drag_coefficient(settings_.law, sp) * vp;
    for (int a = 0; a < 3; ++a) force_[a][i] = f_[i] * slip[a];
  }
  // Σ f_p W_p / V_c and Σ f_p v_p W_p / V_c, serial in particle order (deterministic).
  if (deposit_) {
    deposit_->deposit(f_, out.beta);
  } else {
    const double inv_v = 1.0 / grid_.cell_volume();
    out.beta.assign(grid_.cells(), 0.0);
    for (std::size_t i = 0; i < particles_.size(); ++i) out.beta[cell_[i]] += f_[i] * inv_v;
  }
  for (int a = 0; a < 3; ++a) {
    if (!moving_) {
      out.beta_v[a].clear();
      continue;
    }
    if (deposit_) {
      std::vector<double> fv(particles_.size());
      for (std::size_t i = 0; i < particles_.size(); ++i) fv[i] = f_[i] * velocity_of(particles_[i], a);
      deposit_->deposit(fv, out.beta_v[a]);
      continue;
    }
    const double inv_v = 1.0 / grid_.cell_volume();
    out.beta_v[a].assign(grid_.cells(), 0.0);
    for (std::size_t i = 0; i < particles_.size(); ++i)
      out.beta_v[a][cell_[i]] += f_[i] * velocity_of(particles_[i], a) * inv_v;
  }
  // Filter both (diffusion deposition).
  if (filter_) {
    last_filter_ = filter_->apply(out.beta, beta_warm_);
    if (moving_)
      for (int a = 0; a < 3; ++a) filter_->apply(out.beta_v[a]);
  }
  last_imbalance_ = interphase_force_imbalance(grid_, out, u_cell, force_);
  ++updates_;
}

double interphase_force_imbalance(const Grid& grid, const DragField& field,
                                  const std::array<std::vector<double>, 3>& u_cell,
                                  const std::array<std::vector<double>, 3>& particle_force) {
  const double volume = grid.cell_volume();
  double diff2 = 0, part2 = 0;
  for (int a = 0; a < 3; ++a) {
    long double gas = 0, part = 0;
    for (std::size_t c = 0; c < field.beta.size(); ++c) {
      const double bv = field.beta_v[a].empty() ? 0.0 : field.beta_v[a][c];
      gas += static_cast<long double>(volume * (field.beta[c] * u_cell[a][c] - bv));
    }
    for (double f : particle_force[a]) part += f;
    diff2 += double((gas - part) * (gas - part));
    part2 += double(part * part);
  }
  return part2 > 0 ? std::sqrt(diff2 / part2) : 0.0;
}

}  // namespace gridfree
