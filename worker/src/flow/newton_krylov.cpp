// SPDX-License-Identifier: GPL-3.0-or-later
// Jacobian-free Newton–GMRES with Eisenstat–Walker forcing, backtracking
// and a fixed-point fallback (newton_krylov.h).
#include "flow/newton_krylov.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "flow/parallel.h"

namespace gridfree {
namespace {

constexpr double kGamma = 0.9;       // Eisenstat–Walker choice 2
constexpr double kAlpha = 2.0;
constexpr double kSufficient = 1e-4; // t of the backtracking condition

// y = a + c b.
void add_scaled(const std::vector<double>& a, double c, const std::vector<double>& b, std::vector<double>& y) {
  y.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) y[i] = a[i] + c * b[i];
}

}  // namespace

NewtonKrylov::NewtonKrylov(NewtonKrylovSettings settings, std::vector<double> weights) :
    settings_(settings), weights_(std::move(weights)) {}

double NewtonKrylov::dot(const std::vector<double>& a, const std::vector<double>& b) const {
  if (weights_.empty()) return deterministic_sum(a.size(), [&](std::size_t i) { return a[i] * b[i]; });
  return deterministic_sum(a.size(), [&](std::size_t i) { return weights_[i] * a[i] * b[i]; });
}

double NewtonKrylov::norm(const std::vector<double>& v) const { return std::sqrt(dot(v, v)); }

double NewtonKrylov::gmres(const ResidualMap& directional, const std::vector<double>& x,
                           const std::vector<double>& fx, const std::vector<double>& f_base, double eta,
                           std::vector<double>& s, int& products) const {
  const std::size_t n = fx.size();
  const int m = std::max(1, settings_.restart);
  s.assign(n, 0.0);
  const double beta0 = norm(fx);
  if (!(beta0 > 0)) return 0.0;
  const double h = std::sqrt(std::numeric_limits<double>::epsilon()) * (1.0 + norm(x));
  std::vector<double> r(n), xp, fp;
  for (std::size_t i = 0; i < n; ++i) r[i] = -fx[i];  // residual of J s = −F at s = 0
  double beta = beta0;
  for (int cycle = 0; cycle < std::max(1, settings_.max_cycles); ++cycle) {
    if (beta <= eta * beta0) break;
    std::vector<std::vector<double>> v;
    v.reserve(std::size_t(m) + 1);
    v.emplace_back(n);
    for (std::size_t i = 0; i < n; ++i) v[0][i] = r[i] / beta;
    Eigen::MatrixXd hbar = Eigen::MatrixXd::Zero(m + 1, m);  // Arnoldi: J V_k = V_{k+1} H̄
    Eigen::MatrixXd rot = hbar;                               // H̄ after the Givens rotations
    Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs = Eigen::VectorXd::Zero(m), sn = cs;
    g(0) = beta;
    int k = 0;
    bool breakdown = false;
    for (int j = 0; j < m; ++j) {
      // w = J v_j ≈ (F(x + h v_j) − F(x)) / h   (‖v_j‖ = 1)
      add_scaled(x, h, v[std::size_t(j)], xp);
      directional(xp, fp);
      ++products;
      std::vector<double> w(n);
      for (std::size_t i = 0; i < n; ++i) w[i] = (fp[i] - f_base[i]) / h;
      const double product_norm = norm(w);
      for (int i = 0; i <= j; ++i) {  // modified Gram–Schmidt
        const double hij = dot(w, v[std::size_t(i)]);
        hbar(i, j) = hij;
        add_scaled(w, -hij, v[std::size_t(i)], w);
      }
      const double wn = norm(w);
      hbar(j + 1, j) = wn;
      rot.col(j) = hbar.col(j);
      for (int i = 0; i < j; ++i) {  // earlier rotations on the new column
        const double a = rot(i, j), b = rot(i + 1, j);
        rot(i, j) = cs(i) * a + sn(i) * b;
        rot(i + 1, j) = -sn(i) * a + cs(i) * b;
      }
      const double a = rot(j, j), b = rot(j + 1, j);
      const double rr = std::hypot(a, b);
      cs(j) = rr > 0 ? a / rr : 1.0;
      sn(j) = rr > 0 ? b / rr : 0.0;
      rot(j, j) = rr;
      rot(j + 1, j) = 0.0;
      g(j + 1) = -sn(j) * g(j);
      g(j) = cs(j) * g(j);
      k = j + 1;
      if (!std::isfinite(wn)) return 1.0;  // a non-finite product: no usable direction
      if (wn <= 1e-12 * product_norm) {  // J v_j in the space already: J s = −F solved there
        breakdown = true;
        break;
      }
      v.emplace_back(n);
      for (std::size_t i = 0; i < n; ++i) v.back()[i] = w[i] / wn;
      if (std::abs(g(j + 1)) <= eta * beta0) break;
    }
    // y = R⁻¹ g (upper triangular), s += V_k y.
    Eigen::VectorXd y = rot.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    if (!y.allFinite()) return 1.0;
    for (int i = 0; i < k; ++i) add_scaled(s, y(i), v[std::size_t(i)], s);
    if (breakdown) return 0.0;
    // Restart residual without a product: r = V_{k+1} (β e₁ − H̄ y).
    Eigen::VectorXd c = -hbar.topLeftCorner(k + 1, k) * y;
    c(0) += beta;
    std::fill(r.begin(), r.end(), 0.0);
    for (int i = 0; i <= k; ++i) add_scaled(r, c(i), v[std::size_t(i)], r);
    beta = norm(r);
  }
  return beta / beta0;
}

NewtonStepReport NewtonKrylov::step(const NewtonKrylovMaps& maps, std::vector<double>& fx, std::vector<double>& x,
                                    double target) {
  NewtonStepReport rep;
  const double fn = norm(fx);
  // Eisenstat–Walker choice 2 with its safeguards.
  double eta = settings_.eta_initial;
  if (previous_norm_ > 0) {
    eta = kGamma * std::pow(fn / previous_norm_, kAlpha);
    const double safeguard = kGamma * std::pow(previous_eta_, kAlpha);
    if (safeguard > 0.1) eta = std::max(eta, safeguard);
  }
  if (target > 0 && fn > 0) eta = std::max(eta, 0.5 * target / fn);
  eta = std::min(eta, settings_.eta_max);
  previous_norm_ = fn;
  previous_eta_ = eta;
  rep.eta = eta;

  // The difference quotients need F(x_k) from the same map as F(x_k + h v).
  std::vector<double> s, f_directional;
  if (maps.directional) {
    maps.directional(x, f_directional);
    ++rep.evaluations;
  }
  const ResidualMap& directional = maps.directional ? maps.directional : maps.residual;
  rep.linear_residual =
      gmres(directional, x, fx, maps.directional ? f_directional : fx, eta, s, rep.krylov_iterations);
  rep.evaluations += rep.krylov_iterations;

  if (rep.linear_residual < 1.0) {  // s is a descent direction of ‖F‖²
    std::vector<double> trial, ft;
    double lambda = 1.0;
    for (int b = 0; b <= settings_.max_backtracks; ++b, lambda *= 0.5) {
      add_scaled(x, lambda, s, trial);
      maps.residual(trial, ft);
      ++rep.evaluations;
      rep.trial_norm = norm(ft);
      if (std::isfinite(rep.trial_norm) && rep.trial_norm <= (1.0 - kSufficient * lambda * (1.0 - eta)) * fn) {
        x = std::move(trial);
        fx = std::move(ft);
        rep.newton = true;
        rep.lambda = lambda;
        return rep;
      }
    }
  }
  // Fallback: the plain fixed-point step x + F(x) = G(x).
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += fx[i];
  return rep;
}

NewtonKrylovResult newton_krylov_solve(const NewtonKrylovMaps& maps, const NewtonKrylovSettings& settings,
                                       const std::vector<double>& weights, std::vector<double>& x,
                                       double tolerance, int max_evaluations) {
  NewtonKrylov nk(settings, weights);
  NewtonKrylovResult out;
  std::vector<double> fx;
  maps.residual(x, fx);
  out.evaluations = 1;
  for (;;) {
    out.norm = nk.norm(fx);
    if (!std::isfinite(out.norm)) return out;
    if (out.norm <= tolerance) {
      out.converged = true;
      return out;
    }
    if (out.evaluations >= max_evaluations) return out;
    const NewtonStepReport rep = nk.step(maps, fx, x, tolerance);
    out.evaluations += rep.evaluations;
    ++out.steps;
    if (!rep.newton) {
      ++out.fallbacks;
      maps.residual(x, fx);
      ++out.evaluations;
    }
  }
}

}  // namespace gridfree
