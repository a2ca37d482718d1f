// SPDX-License-Identifier: GPL-3.0-or-later
// The Jacobian-free Newton–GMRES driver (flow/newton_krylov.h) on algebraic
// problems with known roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "flow/newton_krylov.h"

namespace gridfree {
namespace {

// F(x) = −ω (A x + c x³ − b), A = tridiag(−1, 2, −1) (n = 20), b chosen so
// that x*_i = sin(i + 1) is the root: the residual of the fixed-point map
// G(x) = x + F(x), which contracts only at rate ≈ 1 − ω (λ_min(A) + 3c x²)
// ≥ 0.99 (λ_min = 2 − 2 cos(π/21) ≈ 0.0223, 3c x² ≤ 0.03).
struct CubicLaplacian {
  static constexpr int n = 20;
  static constexpr double omega = 0.2, c = 0.01;
  std::vector<double> root, b;
  CubicLaplacian() : root(n), b(n) {
    for (int i = 0; i < n; ++i) root[std::size_t(i)] = std::sin(i + 1.0);
    b = operator_of(root);
  }
  std::vector<double> operator_of(const std::vector<double>& x) const {
    std::vector<double> y(n);
    for (int i = 0; i < n; ++i) {
      const double left = i > 0 ? x[std::size_t(i - 1)] : 0.0, right = i + 1 < n ? x[std::size_t(i + 1)] : 0.0;
      const double xi = x[std::size_t(i)];
      y[std::size_t(i)] = 2 * xi - left - right + c * xi * xi * xi;
    }
    return y;
  }
  void residual(const std::vector<double>& x, std::vector<double>& f) const {
    const std::vector<double> ax = operator_of(x);
    f.resize(n);
    for (int i = 0; i < n; ++i) f[std::size_t(i)] = -omega * (ax[std::size_t(i)] - b[std::size_t(i)]);
  }
};

double max_error(const std::vector<double>& x, const std::vector<double>& y) {
  double e = 0;
  for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - y[i]));
  return e;
}

double norm2(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

TEST(NewtonKrylov, FindsTheRootOfAStiffFixedPointMapInFewerEvaluationsThanIteratingIt) {
  const CubicLaplacian p;
  NewtonKrylovMaps maps;
  maps.residual = [&](const std::vector<double>& x, std::vector<double>& f) { p.residual(x, f); };
  std::vector<double> x(CubicLaplacian::n, 0.0);
  NewtonKrylovSettings settings;
  settings.restart = 10;
  const double tol = 1e-12;
  const NewtonKrylovResult r = newton_krylov_solve(maps, settings, {}, x, tol, 2000);
  ASSERT_TRUE(r.converged) << "‖F‖ = " << r.norm << " after " << r.evaluations << " evaluations";
  // ‖x − x*‖₂ ≤ ‖J⁻¹‖ ‖F‖ ≤ ‖F‖ / (ω λ_min(A)) with λ_min = 2 − 2 cos(π/21)
  // ≈ 0.0223 (the cubic term only adds to J): ≤ 1e-12 / 0.00446 ≈ 2.3e-10.
  EXPECT_LT(max_error(x, p.root), 1e-9);

  // The plain iteration x ← G(x) to the same ‖F‖, counted independently.
  std::vector<double> y(CubicLaplacian::n, 0.0), f;
  int plain = 0;
  for (p.residual(y, f); norm2(f) > tol && plain < 100000; p.residual(y, f), ++plain)
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += f[i];
  EXPECT_LT(r.evaluations * 10, plain) << "Newton-Krylov " << r.evaluations << ", plain " << plain;
}

TEST(NewtonKrylov, SolvesALinearNonsymmetricSystemInOneStepWhenTheKrylovSpaceIsLargeEnough) {
  // F(x) = b − M x, M = 1-D convection–diffusion (upwind), n = 30, x* = cos(i).
  constexpr int n = 30;
  auto apply = [&](const std::vector<double>& x) {
    std::vector<double> y(n);
    for (int i = 0; i < n; ++i) {
      const double left = i > 0 ? x[std::size_t(i - 1)] : 0.0, right = i + 1 < n ? x[std::size_t(i + 1)] : 0.0;
      y[std::size_t(i)] = 3 * x[std::size_t(i)] - 2 * left - right;
    }
    return y;
  };
  std::vector<double> root(n);
  for (int i = 0; i < n; ++i) root[std::size_t(i)] = std::cos(double(i));
  const std::vector<double> b = apply(root);
  NewtonKrylovMaps maps;
  maps.residual = [&](const std::vector<double>& x, std::vector<double>& f) {
    const std::vector<double> mx = apply(x);
    f.resize(n);
    for (int i = 0; i < n; ++i) f[std::size_t(i)] = b[std::size_t(i)] - mx[std::size_t(i)];
  };
  NewtonKrylovSettings settings;
  settings.restart = n;
  settings.max_cycles = 1;
  settings.eta_initial = 1e-10;
  NewtonKrylov nk(settings, {});
  std::vector<double> x(n, 0.0), f;
  maps.residual(x, f);
  const double f0 = nk.norm(f);
  const NewtonStepReport rep = nk.step(maps, f, x);
  EXPECT_TRUE(rep.newton);
  EXPECT_EQ(rep.lambda, 1.0);
  EXPECT_LE(rep.krylov_iterations, n);
  EXPECT_LE(rep.linear_residual, 1e-10);
  // A difference quotient of a linear map is exact up to rounding, ≈ ε/h ≈
  // 1.5e-8 relative per product; over ≤ 30 products the true residual
  // stays below 1e-6 of the initial one.
  EXPECT_LT(nk.norm(f) / f0, 1e-6);
  EXPECT_LT(max_error(x, root), 1e-5);
}

TEST(NewtonKrylov, FallsBackToTheFixedPointStepWhenTheNewtonDirectionDoesNotReduceTheResidual) {
  // G(x) = x − ½ (x − x*): F = −½ (x − x*), J = −½ I. The directional map
  // 2 F(x_k) − F(y) agrees with F at x_k but has the Jacobian +½ I, so GMRES
  // returns an ascent direction, which the line search rejects; every step
  // is then the fixed-point step x + F(x).
  constexpr int n = 5;
  const std::vector<double> root{1, -2, 3, 0.5, -0.25};
  NewtonKrylovMaps maps;
  maps.residual = [&](const std::vector<double>& x, std::vector<double>& f) {
    f.resize(n);
    for (int i = 0; i < n; ++i) f[std::size_t(i)] = -0.5 * (x[std::size_t(i)] - root[std::size_t(i)]);
  };
  const std::vector<double>* base = nullptr;  // x_k of the step under way
  maps.directional = [&](const std::vector<double>& y, std::vector<double>& f) {
    std::vector<double> fk, fy;
    maps.residual(*base, fk);
    maps.residual(y, fy);
    f.resize(n);
    for (int i = 0; i < n; ++i) f[std::size_t(i)] = 2 * fk[std::size_t(i)] - fy[std::size_t(i)];
  };
  NewtonKrylov nk(NewtonKrylovSettings{}, {});
  std::vector<double> x(n, 0.0), f;
  base = &x;
  maps.residual(x, f);
  const std::vector<double> expected{0.5, -1, 1.5, 0.25, -0.125};  // x0 + F(x0) = ½ x*
  const NewtonStepReport rep = nk.step(maps, f, x);
  EXPECT_FALSE(rep.newton);
  EXPECT_EQ(rep.lambda, 0.0);
  EXPECT_GT(rep.trial_norm, nk.norm(f));  // the rejected trials increased ‖F‖
  EXPECT_EQ(max_error(x, expected), 0.0);  // ½ x* exactly representable

  // The whole solve still converges, on fallback steps only: ‖F‖ halves per
  // step, from ‖F(0)‖ = ½‖x*‖ ≈ 1.9 to 1e-10 in about 35 steps.
  std::vector<double> z(n, 0.0);
  base = &z;
  const NewtonKrylovResult r = newton_krylov_solve(maps, NewtonKrylovSettings{}, {}, z, 1e-10, 10000);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.fallbacks, r.steps);
  EXPECT_GT(r.steps, 0);
  EXPECT_LT(max_error(z, root), 1e-9);  // |x − x*| = 2 |F| ≤ 2e-10
}

TEST(NewtonKrylov, WeightedNormScalesEachEntry) {
  NewtonKrylov nk(NewtonKrylovSettings{}, {4.0, 0.25});
  EXPECT_DOUBLE_EQ(nk.norm({1.0, 4.0}), std::sqrt(4.0 + 4.0));
}

}  // namespace
}  // namespace gridfree
