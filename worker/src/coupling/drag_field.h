// The interphase drag field β (and βv̄) on the grid (PHYSICS.md §3).
//
// Particles:  f_p = D(ε_g,c(p), |u_c(p) − v_p|) V_p with the filtered ε_g and
//             the cell-centre gas velocity of the particle's cell, then
//               β   = filter( Σ_{p∈c} f_p / V_c ),
//               βv̄ = filter( Σ_{p∈c} f_p v_p / V_c )   (skipped when all v_p = 0)
//             with the same filter as ε_s (none for centroid deposition).
// Uniform:    β = φ D(ε_g, |u_c|) per cell, no particles (Model A: β = ε_s D).
//
// The filter of β starts each step from that step's result of the previous
// update (FilterWarmStart): β changes little between outer iterations.
// f_p is computed in parallel (one slot per particle); the deposition is a
// serial loop in particle order, so β is bitwise independent of the thread count.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "deposition/filter.h"
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

class ParticleDragField {
 public:
  // `filter` = nullopt for centroid deposition.
  ParticleDragField(const Grid& grid, std::vector<Particle> particles, const DragSettings& settings,
                    std::optional<FilterSettings> filter);

  void compute(const std::vector<double>& eps_g, const std::array<std::vector<double>, 3>& u_cell, DragField& out);

  const FilterStats& last_filter() const { return last_filter_; }
  int updates() const { return updates_; }

 private:
  Grid grid_;
  std::vector<Particle> particles_;
  std::vector<std::size_t> cell_;  // cell of each particle centre
  DragSettings settings_;
  std::optional<DiffusionFilter> filter_;  // built once: matrix and multigrid reused every update
  FilterWarmStart beta_warm_;              // β's filter steps of the last update (βv̄: cold, saves memory)
  bool moving_ = false;            // some particle has a non-zero velocity
  std::vector<double> f_;          // f_p per particle
  FilterStats last_filter_;
  int updates_ = 0;
};

}  // namespace gridfree
