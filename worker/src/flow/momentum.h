// SPDX-License-Identifier: GPL-3.0-or-later
// Momentum equation of one gas-velocity component on its faces.
//
// Model A (PHYSICS.md §1), steady, on the control volume V centred on face P
// (normal to axis a; the CV spans the two cells L, R sharing the face):
//
//   Σ_cv-faces F φ_f − Σ μ A ∂φ/∂n  =  ε̄_P A_a (p_L − p_R) + ε̄_P ρ g_a V
//        + (μ/3) A_a [(∇·u)_R − (∇·u)_L] − V β̄_P (φ_P − v̄_s,P) + V S_P
//
// discretized as   a_P φ_P = Σ_nb a_nb φ_nb + b_P   with
//   a_nb = μ A/Δ + max(∓F, 0)                (FOU convection + diffusion)
//   a_P  = Σ a_nb + Σ_out F − Σ_in F + V β̄_P (implicit drag)
//   b_P  = pressure, gravity, V (βv̄)‾, −(TVD − FOU) convective flux of the
//          previous iterate (deferred correction), manufactured source.
// CV-face mass fluxes F are means of the two scalar-grid face fluxes the CV
// face cuts. Under-relaxation: a_P ← a_P/α, b_P += (1−α)/α · a_P φ_P^old.
// SIMPLEC coefficient: d_P = A_a ε̄_P / (a_P/α − Σ a_nb)  (0 on fixed faces).
#pragma once

#include <array>
#include <vector>

#include "flow/fields.h"
#include "flow/flow_state.h"
#include "linalg/stencil.h"

namespace gridfree {

struct MomentumSystem {
  explicit MomentumSystem(const Grid& face_grid) : eq(face_grid) {}
  Stencil7 eq;          // on the face grid of the component's axis
  double residual = 0;  // Σ |b + Σ a_nb φ_nb − a_P φ_P| (before relaxation)
  double scale = 0;     // Σ |a_P φ_P| (before relaxation)
  double residual_l2 = 0;  // ||b + Σ a_nb φ_nb − a_P φ_P||₂ (what the linear solver sees)
  double rhs_l2 = 0;       // ||b||₂ of the relaxed system
};

// Relaxation of the deferred correction (docs/SOLVER.md "Stalled outer
// iterations"): the correction DC_P entering b_P is
//   DC_P ← w · DC_P(φ) + (1 − w) · DC_P(last assembly),
// per momentum component and face; the first assembly records DC_P(φ). At a
// fixed point DC_P(φ) equals the one held, so the steady solution is that
// of the unrelaxed equations; only the path to it is damped.
struct CorrectionRelaxation {
  explicit CorrectionRelaxation(double weight_) : weight(weight_) {}
  double weight;                             // w, the share of the new correction
  std::array<std::vector<double>, 3> held;   // per component: DC of the last assembly (empty: none yet)
};

// Assembles the a-momentum equation into `sys` (whose eq must live on
// FaceLayout(grid, axis).as_grid(grid)) and the SIMPLEC coefficients into
// `d`. `mass_flux` = F of mass_flux.h, `divergence` = ∇·u per cell,
// `relax` = α_u; `relaxation`, when given, relaxes the deferred correction.
void assemble_momentum(const FlowProblem& problem, const FlowState& state,
                       const FaceVector& mass_flux, const CellField& divergence, int axis,
                       double relax, MomentumSystem& sys, FaceField& d,
                       CorrectionRelaxation* relaxation = nullptr);

}  // namespace gridfree
