// SPDX-License-Identifier: GPL-3.0-or-later
// Assembly of one momentum component (equation in momentum.h).
#include "flow/momentum.h"

#include <algorithm>
#include <cmath>

#include "flow/parallel.h"

namespace gridfree {
namespace {

// Sentinel of `shifted`: no face there.
constexpr long kNoFace = -1;

// Index of the face k steps along direction b from face coordinate x
// (k = ±1 the neighbour, ±2 the one beyond) in a face layout: wrapped on
// periodic axes, kNoFace beyond a non-periodic boundary. Returns an index,
// not coordinates: this runs for every face of every assembly.
long shifted(const Grid& g, const FaceLayout& lay, std::array<int, 3> x, int b, int k) {
  const int n = lay.n[b];
  int v = x[b] + k;
  if (v < 0 || v >= n) {
    if (!g.periodic[b]) return kNoFace;
    v = ((v % n) + n) % n;
  }
  x[b] = v;
  return static_cast<long>(lay.index(x));
}

// Scalar-grid face index (along b) of cell x's face on `side`.
std::size_t cell_face(const Grid& g, const FaceLayout& lay, std::array<int, 3> x, int b, int side) {
  if (side == 1) x[b] = (g.periodic[b] && x[b] + 1 == g.n[b]) ? 0 : x[b] + 1;
  return lay.index(x);
}

}  // namespace

void assemble_momentum(const FlowProblem& problem, const FlowState& state,
                       const FaceVector& mass_flux, const CellField& divergence, int a,
                       double relax, MomentumSystem& sys, FaceField& d, CorrectionRelaxation* relaxation) {
  const Grid& g = problem.grid;
  const FaceLayout lay(g, a);
  const FaceField& u = state.u[a];
  const double mu = problem.gas.mu;
  const double V = g.cell_volume();
  const double Aa = g.face_area(a);
  const bool tvd = problem.convection != Limiter::kFou;
  const std::vector<double>* source =
      (problem.sources && !problem.sources->momentum[a].empty()) ? &problem.sources->momentum[a]
                                                                 : nullptr;
  Stencil7& eq = sys.eq;
  if (d.size() != lay.size()) d = FaceField(g, a, 0.0);
  // Per-row residual and |a_P φ_P| (0 on fixed faces), summed below; freed on
  // return, before the linear solve allocates its vectors.
  std::vector<double> row_residual(lay.size()), row_scale(lay.size());
  auto nb = neighbour_arrays(eq);
  const long faces = static_cast<long>(lay.size());
  // Role of the faces at each position along the normal axis.
  std::vector<FaceRole> role_at(std::size_t(lay.n[a]));
  for (int f = 0; f < lay.n[a]; ++f) role_at[std::size_t(f)] = face_role(g, problem.bc, a, f);
  // The relaxed correction (relaxation given): the last one per face.
  std::vector<double>* dc_store = relaxation && tvd ? &relaxation->held[std::size_t(a)] : nullptr;
  const bool dc_first = dc_store && dc_store->empty();
  if (dc_first) dc_store->assign(lay.size(), 0.0);

#pragma omp parallel for schedule(static) if (faces > kMinParallel)
  for (long fl = 0; fl < faces; ++fl) {
    const std::size_t P = std::size_t(fl);
    const std::array<int, 3> x = face_coords(lay, P);
    const int fa = x[a];
    for (int b = 0; b < 3; ++b) (*nb[b][0])[P] = (*nb[b][1])[P] = 0.0;
    if (role_at[std::size_t(fa)] == FaceRole::kFixed) {
      eq.ap[P] = 1.0;
      eq.b[P] = u[P];
      d[P] = 0.0;
      row_residual[P] = row_scale[P] = 0.0;
      continue;
    }
    // Cells L (low) and R (high) of the face; a missing one is a ghost.
    const bool hasL = g.periodic[a] || fa > 0;
    const bool hasR = g.periodic[a] || fa < g.n[a];
    std::array<int, 3> xl = x, xr = x;
    xl[a] = fa == 0 ? g.n[a] - 1 : fa - 1;
    if (fa == g.n[a]) xr[a] = g.n[a] - 1;  // unused when !hasR

    double sum_nb = 0, net_out = 0, ap_fold = 0, b = 0, sum_matrix_nb = 0, sum_nb_phi = 0, dc = 0;
    for (int bd = 0; bd < 3; ++bd) {
      const FaceLayout& lb = mass_flux[bd].layout;
      for (int side = 0; side < 2; ++side) {
        const int dir = side == 0 ? -1 : 1;
        // Mass flux F (along +bd) through this CV face, and diffusion coefficient.
        double F = 0, D = 0;
        long N = shifted(g, lay, x, bd, dir);  // the neighbour face, or kNoFace
        TangentialGhost ghost{1.0, 0.0, 0.0};
        if (bd == a) {
          const bool has_cell = side == 0 ? hasL : hasR;
          if (has_cell) {
            const std::array<int, 3>& xc = side == 0 ? xl : xr;
            F = 0.5 * (mass_flux[a][cell_face(g, lb, xc, a, 0)] + mass_flux[a][cell_face(g, lb, xc, a, 1)]);
            D = mu * g.face_area(a) / g.h(a);
          } else {
            F = mass_flux[a][P];  // ghost cell beyond an outflow: zero gradient, no viscous flux
            N = kNoFace;
          }
        } else {
          double sumF = 0;
          int count = 0;
          if (hasL) { sumF += mass_flux[bd][cell_face(g, lb, xl, bd, side)]; ++count; }
          if (hasR) { sumF += mass_flux[bd][cell_face(g, lb, xr, bd, side)]; ++count; }
          F = sumF / count;
          D = mu * g.face_area(bd) / g.h(bd);
          if (N == kNoFace) {
            ghost = tangential_ghost(problem.bc[bd][side]);
            D *= ghost.diffusion;
          }
        }
        const double anb = D + std::max(side == 0 ? F : -F, 0.0);
        sum_nb += anb;
        net_out += side == 0 ? -F : F;
        // Where the neighbour value comes from.
        if (N == kNoFace) {  // ghost: φ_g = scale φ_P + value
          ap_fold -= anb * ghost.scale;
          b += anb * ghost.value;
        } else {
          if (std::size_t(N) == P) {
            ap_fold -= anb;  // a single periodic cell: the neighbour is P itself
          } else if (bd == a && !g.periodic[a] && role_at[std::size_t(fa + dir)] == FaceRole::kFixed) {
            b += anb * u[N];
          } else {
            (*nb[bd][side])[P] = anb;
            sum_matrix_nb += anb;
            sum_nb_phi += anb * u[N];
          }
        }
        // Deferred correction: −F_out (φ_TVD − φ_FOU) of the previous iterate.
        if (tvd && N != kNoFace && std::size_t(N) != P) {
          // Upwind C (the neighbour or P), downwind D, and U one beyond C.
          const bool from_neighbour = side == 0 ? F > 0 : F < 0;
          const long U = shifted(g, lay, x, bd, from_neighbour ? 2 * dir : -dir);
          if (U != kNoFace) {
            const double phi_c = from_neighbour ? u[N] : u[P];
            const double phi_d = from_neighbour ? u[P] : u[N];
            const double phi_u = u[U];
            const double face = limited_face_value(problem.convection, phi_u, phi_c, phi_d);
            const double f_out = side == 0 ? -F : F;
            if (dc_store) dc -= f_out * (face - phi_c);
            else b -= f_out * (face - phi_c);
          }
        }
      }
    }
    if (dc_store) {  // relaxed correction: a share of the new one, the rest the last one used
      double& held = (*dc_store)[P];
      if (!dc_first) dc = relaxation->weight * dc + (1.0 - relaxation->weight) * held;
      held = dc;
      b += dc;
    }
    // Sources: pressure gradient, gravity, extra viscous term, drag, manufactured.
    const double eps = state.eps_face[a][P];
    const double pL = hasL ? state.p[g.index(xl[0], xl[1], xl[2])] : problem.bc[a][0].pressure_dyn_cm2;
    const double pR = hasR ? state.p[g.index(xr[0], xr[1], xr[2])] : problem.bc[a][1].pressure_dyn_cm2;
    b += eps * Aa * (pL - pR);
    b += eps * problem.gas.rho * problem.gas.gravity[a] * V;
    if (hasL && hasR) {
      const double divL = divergence[g.index(xl[0], xl[1], xl[2])];
      const double divR = divergence[g.index(xr[0], xr[1], xr[2])];
      b += mu / 3.0 * Aa * (divR - divL);
    }
    // Face averages β̄ and (βv̄)‾ of the cells L, R (zero-gradient ghost).
    const std::size_t cl = g.index(xl[0], xl[1], xl[2]), cr = g.index(xr[0], xr[1], xr[2]);
    const auto face_mean = [&](const std::vector<double>& cell) {
      const double lo = hasL ? cell[cl] : cell[cr];
      const double hi = hasR ? cell[cr] : cell[cl];
      return 0.5 * (lo + hi);
    };
    if (!state.drag.beta_v[a].empty()) b += V * face_mean(state.drag.beta_v[a]);
    if (source) b += V * (*source)[P];
    const double ap = sum_nb + net_out + ap_fold + V * face_mean(state.drag.beta);
    row_residual[P] = b + sum_nb_phi - ap * u[P];
    row_scale[P] = std::abs(ap * u[P]);

    // Relaxation (the residual b + Σ a_nb φ_nb − a_P φ_P at the current
    // iterate is the same before and after it) and the SIMPLEC coefficient.
    const double ap_relaxed = ap / relax;
    eq.ap[P] = ap_relaxed;
    eq.b[P] = b + (ap_relaxed - ap) * u[P];
    const double denom = std::max(ap_relaxed - sum_matrix_nb, 1e-3 * ap_relaxed);
    d[P] = Aa * eps / denom;
  }

  // Residual sums in a fixed order (independent of the thread count).
  const std::vector<double>& r = row_residual;
  sys.residual = deterministic_sum(r.size(), [&](std::size_t P) { return std::abs(r[P]); });
  sys.residual_l2 = std::sqrt(deterministic_sum(r.size(), [&](std::size_t P) { return r[P] * r[P]; }));
  sys.rhs_l2 = std::sqrt(deterministic_sum(r.size(), [&](std::size_t P) { return eq.b[P] * eq.b[P]; }));
  sys.scale = deterministic_sum(r.size(), [&](std::size_t P) { return row_scale[P]; });
}

}  // namespace gridfree
