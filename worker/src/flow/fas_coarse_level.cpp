// SPDX-License-Identifier: GPL-3.0-or-later
// The coarse level of the two-grid FAS prototype (fas_coarse_level.h).
#include "flow/fas_coarse_level.h"

#include "coupling/solids_fraction.h"
#include "flow/initial_state.h"

namespace gridfree {

std::unique_ptr<FasCoarseLevel> make_fas_coarse_level(const JobSpec& job, const ParticleSet& particles,
                                                      const Grid& grid, CellField p, FaceVector u) {
  const CaseSpec& cs = job.case_spec;
  const NumericsSpec& num = job.numerics;
  const double d = cs.particle_diameter_cm;
  auto lv = std::make_unique<FasCoarseLevel>();
  FlowProblem& problem = lv->problem;
  problem.grid = grid;
  problem.bc = cs.boundaries;
  problem.gas = {cs.gas.density_g_cm3, cs.gas.viscosity_g_cm_s, cs.gravity_cm_s2};
  problem.convection = num.convection;
  const auto* uniform = std::get_if<UniformSpec>(&cs.particles);
  const SolidsFraction sf = uniform ? uniform_solids_fraction(grid, uniform->solids_fraction)
                                    : deposit_solids_fraction(grid, particles.particles, num.deposition, d,
                                                              num.tolerances.filter);
  lv->drag_settings = {num.drag, d, cs.gas.density_g_cm3, cs.gas.viscosity_g_cm_s};
  if (uniform) {
    lv->uniform_phi = uniform->solids_fraction;
  } else {
    TransferSettings transfer{kernel_params(num.deposition, d), num.deposition.sampling, std::nullopt};
    if (is_filtered(num.deposition)) transfer.filter = filter_settings(num.deposition, d, num.tolerances.filter);
    lv->particle_drag.emplace(grid, particles.particles, lv->drag_settings, transfer);
  }
  FasCoarseLevel* self = lv.get();
  lv->level.problem = &lv->problem;
  lv->level.state = &lv->state;
  lv->level.drag = [self](const FlowState& st, DragField& out) {
    const Grid& g = self->problem.grid;
    const auto u_cell = cell_centre_velocity(g, st.u);
    if (self->uniform_phi >= 0) uniform_drag_field(g, self->drag_settings, self->uniform_phi, st.eps_g, u_cell, out);
    else self->particle_drag->compute(st.eps_g, u_cell, out);
  };
  warm_start(problem, sf.eps_s, lv->level.drag, lv->state, false);
  lv->state.p = std::move(p);
  lv->state.u = std::move(u);
  return lv;
}

}  // namespace gridfree
