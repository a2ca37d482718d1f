// SPDX-License-Identifier: GPL-3.0-or-later
#include "verify/manufactured_flow.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "flow/flow_state.h"
#include "flow/simple_loop.h"
#include "verify/analytic.h"

namespace gridfree {
namespace {

constexpr double kRho = 1.0;
constexpr double kMu = 0.01;
constexpr double kStep = 1e-3;  // finite-difference step of analytic.h
const double kWaveK = 2.0 * std::numbers::pi;

// The manufactured fields (header comment); z plays no part.
double eps_exact(const Point3& x) { return 0.6 + 0.15 * std::sin(kWaveK * x[0]) * std::sin(kWaveK * x[1]); }
double p_exact(const Point3& x) { return 0.5 * std::cos(kWaveK * x[0]) * std::sin(kWaveK * x[1]); }
double beta_exact(const Point3& x) { return 2.0 * (1.0 + 0.5 * std::cos(kWaveK * x[0]) * std::cos(kWaveK * x[1])); }
double u_exact(int a, const Point3& x) {
  if (a == 0) return 1.0 + 0.5 * std::sin(kWaveK * x[0]) * std::cos(kWaveK * x[1]);
  if (a == 1) return 0.8 + 0.4 * std::cos(kWaveK * x[0]) * std::sin(2.0 * kWaveK * x[1]);
  return 0.0;
}

// S_m = ∇·(ε ρ u).
double mass_source(const Point3& x) {
  double s = 0;
  for (int b = 0; b < 3; ++b) {
    const ScalarFn flux = [b](const Point3& y) { return eps_exact(y) * kRho * u_exact(b, y); };
    s += partial(flux, x, b, kStep);
  }
  return s;
}

// S_a = ∇·(ε ρ u u_a) + ε ∂_a p − μ[∇²u_a + ⅓ ∂_a(∇·u)] + β u_a.
double momentum_source(int a, const Point3& x) {
  double convection = 0, laplacian = 0, grad_div = 0;
  const ScalarFn ua = [a](const Point3& y) { return u_exact(a, y); };
  for (int b = 0; b < 3; ++b) {
    const ScalarFn flux = [a, b](const Point3& y) { return eps_exact(y) * kRho * u_exact(b, y) * u_exact(a, y); };
    convection += partial(flux, x, b, kStep);
    laplacian += partial2(ua, x, b, b, kStep);
    const ScalarFn ub = [b](const Point3& y) { return u_exact(b, y); };
    grad_div += partial2(ub, x, a, b, kStep);
  }
  const ScalarFn p = p_exact;
  return convection + eps_exact(x) * partial(p, x, a, kStep) - kMu * (laplacian + grad_div / 3.0) +
         beta_exact(x) * u_exact(a, x);
}

// Position of face f (flat index) normal to `axis`.
Point3 face_centre(const Grid& g, const FaceLayout& lay, std::size_t f) {
  const auto x = face_coords(lay, f);
  Point3 pos{};
  for (int b = 0; b < 3; ++b) pos[b] = b == lay.axis ? x[b] * g.h(b) : g.centre(b, x[b]);
  return pos;
}

Point3 cell_centre(const Grid& g, std::size_t c) {
  const auto x = cell_coords(g, c);
  return {g.centre(0, x[0]), g.centre(1, x[1]), g.centre(2, x[2])};
}

}  // namespace

double manufactured_flow_error(Limiter scheme, int n, int* iterations) {
  FlowProblem problem;
  problem.grid.n = {n, n, 1};
  problem.grid.length = {1.0, 1.0, 1.0 / n};
  problem.grid.periodic = {true, true, true};
  for (auto& axis : problem.bc)
    for (auto& side : axis) side.kind = BoundaryKind::kPeriodic;
  problem.gas.rho = kRho;
  problem.gas.mu = kMu;
  problem.convection = scheme;
  const Grid& g = problem.grid;

  FlowSources sources;
  sources.mass.resize(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) sources.mass[c] = mass_source(cell_centre(g, c));
  FlowState state;
  state.u = make_face_vector(g);
  for (int a = 0; a < 3; ++a) {
    const FaceLayout& lay = state.u[a].layout;
    sources.momentum[a].resize(lay.size());
    for (std::size_t f = 0; f < lay.size(); ++f) {
      const Point3 x = face_centre(g, lay, f);
      sources.momentum[a][f] = momentum_source(a, x);
      state.u[a][f] = u_exact(a, x);  // start from the exact field: only the discretization error remains
    }
  }
  problem.sources = &sources;
  state.eps_g.resize(g.cells());
  state.p.resize(g.cells());
  state.drag.beta.resize(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) {
    const Point3 x = cell_centre(g, c);
    state.eps_g[c] = eps_exact(x);
    state.p[c] = p_exact(x);
    state.drag.beta[c] = beta_exact(x);
  }

  // Steady to 1e-10 (the iterative error must stay far below the smallest
  // discretization error, ~1e-5 on 128²). The inner solves keep the
  // production settings (momentum: 0.1 × the current residual, pressure:
  // 1e-2): they only set how fast the outer iterations reach the fixed
  // point, not where it is, and solving each one to 1e-12 cost most of the time.
  SimpleSettings settings;
  settings.steady_tolerance = 1e-10;
  settings.max_iterations = 5000;
  const SimpleOutcome out = run_simple(problem, settings, state, {}, {}, {});
  if (iterations) *iterations = out.iterations;
  if (out.status != SolveStatus::kConverged)
    throw std::runtime_error("the manufactured problem on " + std::to_string(n) + "x" + std::to_string(n) +
                             " did not converge: " + out.reason);

  double sum = 0;
  std::size_t count = 0;
  for (int a = 0; a < 2; ++a) {
    const FaceLayout& lay = state.u[a].layout;
    for (std::size_t f = 0; f < lay.size(); ++f) {
      sum += std::abs(state.u[a][f] - u_exact(a, face_centre(g, lay, f)));
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}

OrderStudy manufactured_flow_study(Limiter scheme) {
  OrderStudy s;
  s.equation = "momentum_continuity_drag";
  s.scheme = std::string(limiter_name(scheme));
  s.norm = "L1 face velocity";
  for (const auto& info : limiters())
    if (info.limiter == scheme) s.expected_order = info.formal_order;
  return s;
}

GridOutcome manufactured_flow_outcome(Limiter scheme, int n) {
  GridOutcome o;
  try {
    o.error = manufactured_flow_error(scheme, n, &o.iterations);
  } catch (const std::runtime_error& e) {
    o.failure = e.what();
  }
  return o;
}

OrderStudy manufactured_flow_order(Limiter scheme, const std::vector<int>& grids) {
  OrderStudy s = manufactured_flow_study(scheme);
  std::vector<GridOutcome> outcomes;
  for (int n : grids) {
    outcomes.push_back(manufactured_flow_outcome(scheme, n));
    if (!outcomes.back().failure.empty()) break;
  }
  finish_study(s, grids, outcomes);
  return s;
}

}  // namespace gridfree
