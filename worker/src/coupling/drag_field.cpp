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
    : grid_(grid), particles_(std::move(particles)), settings_(settings) {
  if (filter) filter_.emplace(grid_, *filter);
  cell_.resize(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    cell_[i] = cell_of_particle(grid_, particles_[i]);
    const Particle& p = particles_[i];
    if (p.u != 0 || p.v != 0 || p.w != 0) moving_ = true;
  }
  f_.resize(particles_.size());
}

void ParticleDragField::compute(const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell,
                                DragField& out) {
  const long np = static_cast<long>(particles_.size());
  // f_p = D V_p for every particle (independent: parallel).
#pragma omp parallel for schedule(static) if (np > kMinParallelParticles)
  for (long il = 0; il < np; ++il) {
    const std::size_t i = std::size_t(il);
    const Particle& p = particles_[i];
    const std::size_t c = cell_[i];
    const double vp = std::numbers::pi * p.d * p.d * p.d / 6.0;
    const DragState st = state_of(settings_, eps_g[c], speed(u_cell, c, p.u, p.v, p.w));
    DragState sp = st;
    sp.d = p.d;
    f_[i] = drag_coefficient(settings_.law, sp) * vp;
  }
  // Σ f_p / V_c and Σ f_p v_p / V_c, serial in particle order (deterministic).
  const double inv_v = 1.0 / grid_.cell_volume();
  out.beta.assign(grid_.cells(), 0.0);
  for (std::size_t i = 0; i < particles_.size(); ++i) out.beta[cell_[i]] += f_[i] * inv_v;
  for (int a = 0; a < 3; ++a) {
    if (!moving_) {
      out.beta_v[a].clear();
      continue;
    }
    out.beta_v[a].assign(grid_.cells(), 0.0);
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      const Particle& p = particles_[i];
      const double v = a == 0 ? p.u : (a == 1 ? p.v : p.w);
      out.beta_v[a][cell_[i]] += f_[i] * v * inv_v;
    }
  }
  // Filter both (diffusion deposition).
  if (filter_) {
    last_filter_ = filter_->apply(out.beta, beta_warm_);
    if (moving_)
      for (int a = 0; a < 3; ++a) filter_->apply(out.beta_v[a]);
  }
  ++updates_;
}

}  // namespace gridfree
