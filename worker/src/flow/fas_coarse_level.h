// SPDX-License-Identifier: GPL-3.0-or-later
// The coarse level of the two-grid FAS prototype (two_grid_fas.h): the job
// on the nested start's grid, with ε_s deposited and the drag computed from
// the same particles as on the fine grid (as in solve.cpp), started from
// the nested start's converged p and u.
#pragma once

#include <memory>
#include <optional>

#include "coupling/drag_field.h"
#include "flow/two_grid_fas.h"
#include "job/job_spec.h"
#include "particles/particle.h"

namespace gridfree {

struct FasCoarseLevel {
  FlowProblem problem;
  FlowState state;
  DragSettings drag_settings;
  std::optional<ParticleDragField> particle_drag;
  double uniform_phi = -1;  // ≥ 0 for a uniform continuum bed
  FasLevel level;           // points into this object: never copied or moved
  FasCoarseLevel() = default;
  FasCoarseLevel(const FasCoarseLevel&) = delete;
  FasCoarseLevel& operator=(const FasCoarseLevel&) = delete;
};

std::unique_ptr<FasCoarseLevel> make_fas_coarse_level(const JobSpec& job, const ParticleSet& particles,
                                                      const Grid& grid, CellField p, FaceVector u);

}  // namespace gridfree
