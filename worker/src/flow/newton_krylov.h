// SPDX-License-Identifier: GPL-3.0-or-later
// Jacobian-free Newton–Krylov for a fixed-point residual F(x) = G(x) − x
// (docs/SOLVER.md "Newton–Krylov prototype").
//
// One step from x_k with F_k = F(x_k):
//   η_k   Eisenstat–Walker choice 2 (SIAM J. Sci. Comput. 17 (1996) 16):
//         η_k = γ (‖F_k‖/‖F_{k−1}‖)^α, γ = 0.9, α = 2, kept ≥ γ η_{k−1}^α
//         when that exceeds 0.1, ≤ η_max, and ≥ ½ target/‖F_k‖ (no
//         oversolving below the caller's tolerance); η_0 = η_initial;
//   s     restarted GMRES(m) from s = 0 on J s = −F_k until
//         ‖F_k + J s‖ ≤ η_k ‖F_k‖ or max_cycles × m products, with
//         J v ≈ (F(x_k + h v) − F(x_k)) / h,  h = √ε_mach (1 + ‖x_k‖) / ‖v‖
//         (with a separate directional map, F(x_k) is evaluated once more
//         with it: the quotient must difference one map);
//   λ     backtracking on ‖F‖: accept x_k + λ s when
//         ‖F(x_k + λ s)‖ ≤ (1 − t λ (1 − η_k)) ‖F_k‖, t = 1e-4, halving λ
//         up to max_backtracks times;
//   else  fallback: the plain fixed-point step x_{k+1} = x_k + F_k = G(x_k).
// Since F = G − x, J = G' − I: the fixed-point map acts as the right
// preconditioner of Newton's linear systems by construction.
//
// Norms and inner products are weighted, ⟨a, b⟩ = Σ w_i a_i b_i (w from the
// caller; the flow solver weights each of u_x, u_y, u_z, p by 1/its RMS),
// and summed in a fixed order (flow/parallel.h), so the result does not
// depend on the thread count.
#pragma once

#include <functional>
#include <vector>

namespace gridfree {

struct NewtonKrylovSettings {
  int restart = 10;         // m of GMRES(m): Krylov vectors kept
  int max_cycles = 2;       // GMRES restarts + 1
  double eta_initial = 0.5;
  double eta_max = 0.9;
  int max_backtracks = 3;
};

// fx = F(x).
using ResidualMap = std::function<void(const std::vector<double>& x, std::vector<double>& fx)>;

struct NewtonKrylovMaps {
  ResidualMap residual;     // trial points of the line search
  ResidualMap directional;  // F for the Jacobian products (empty: residual); must equal F at x_k up to O(h)
};

struct NewtonStepReport {
  bool newton = false;        // the Newton step was accepted (else the fallback was taken)
  int evaluations = 0;        // F evaluations in this step
  int krylov_iterations = 0;  // Jacobian products
  double eta = 0;             // forcing term used
  double linear_residual = 0; // ‖F_k + J s‖ / ‖F_k‖ reached by GMRES
  double lambda = 0;          // accepted step length (0 with the fallback)
  double trial_norm = 0;      // ‖F‖ at the last trial point
};

class NewtonKrylov {
 public:
  NewtonKrylov(NewtonKrylovSettings settings, std::vector<double> weights);

  // x = x_k, fx = F(x_k) on entry; x = x_{k+1} on return, and fx =
  // F(x_{k+1}) when the Newton step was accepted (after the fallback fx is
  // left as F(x_k): the caller evaluates F at the new x). `target` is the
  // ‖F‖ the caller will accept (bounds η from below; 0 = none).
  NewtonStepReport step(const NewtonKrylovMaps& maps, std::vector<double>& fx, std::vector<double>& x,
                        double target = 0.0);

  double norm(const std::vector<double>& v) const;
  void set_weights(std::vector<double> weights) { weights_ = std::move(weights); }

 private:
  double dot(const std::vector<double>& a, const std::vector<double>& b) const;
  // GMRES(m) on J s = −fx with J v = (directional(x + h v) − f_base)/h;
  // returns ‖fx + J s‖ / ‖fx‖ and counts products.
  double gmres(const ResidualMap& directional, const std::vector<double>& x, const std::vector<double>& fx,
               const std::vector<double>& f_base, double eta, std::vector<double>& s, int& products) const;

  NewtonKrylovSettings settings_;
  std::vector<double> weights_;
  double previous_norm_ = -1;  // ‖F_{k−1}‖
  double previous_eta_ = -1;
};

// Solves F(x) = 0 from x by NewtonKrylov steps until ‖F‖ ≤ tolerance or
// max_evaluations F evaluations (the step's trial evaluation is reused as
// the next F_k only when the Newton step was accepted).
struct NewtonKrylovResult {
  bool converged = false;
  double norm = 0;      // ‖F(x)‖ at return
  int steps = 0;
  int fallbacks = 0;
  int evaluations = 0;
};
NewtonKrylovResult newton_krylov_solve(const NewtonKrylovMaps& maps, const NewtonKrylovSettings& settings,
                                       const std::vector<double>& weights, std::vector<double>& x,
                                       double tolerance, int max_evaluations);

}  // namespace gridfree
