// SPDX-License-Identifier: GPL-3.0-or-later
// Global profile least squares for f0 + c h^p (see power_fit.h).
#include "extrap/power_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "extrap/least_squares.h"

namespace gridfree {
namespace {

// The problem in scaled variables x = h/h_max ∈ (0, 1], g = (f − f_ref)/f_scale.
struct Scaled {
  Eigen::VectorXd x, log_x, g, w;
  double h_max = 1, f_ref = 0, f_scale = 1;
};

Scaled scale_problem(const Series& s, const std::vector<double>& w) {
  const auto n = static_cast<Eigen::Index>(s.size());
  Scaled sp;
  sp.h_max = *std::max_element(s.h.begin(), s.h.end());
  sp.x.resize(n);
  sp.log_x.resize(n);
  sp.g.resize(n);
  sp.w = Eigen::Map<const Eigen::VectorXd>(w.data(), n);
  sp.f_ref = 0;
  for (Eigen::Index i = 0; i < n; ++i) sp.f_ref += sp.w(i) * s.f[static_cast<std::size_t>(i)];
  double spread = 0;
  for (double fi : s.f) spread = std::max(spread, std::fabs(fi - sp.f_ref));
  sp.f_scale = spread > 0 ? spread : 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sp.x(i) = s.h[k] / sp.h_max;
    sp.log_x(i) = std::log(sp.x(i));
    sp.g(i) = (s.f[k] - sp.f_ref) / sp.f_scale;
  }
  return sp;
}

// Linear fit g ≈ a + b x^p at fixed p.
struct AtP {
  double p = 0, a = 0, b = 0, S = 0;
  Eigen::VectorXd xp, r;
};

AtP solve_at(const Scaled& sp, double p) {
  AtP out;
  out.p = p;
  out.xp = (p * sp.log_x.array()).exp().matrix();
  Eigen::MatrixXd A(sp.x.size(), 2);
  A.col(0).setOnes();
  A.col(1) = out.xp;
  const LinearFit fit = weighted_least_squares(A, sp.g, sp.w);
  out.a = fit.x(0);
  out.b = fit.x(1);
  out.r = fit.residuals;
  out.S = fit.sum_of_squares;
  return out;
}

// S(p) of the dense scan, the same minimum as solve_at(sp, p).S without its
// allocations and its QR: the closed form of the two-parameter fit in
// centred variables, residuals (g − ḡ) − b (x^p − x̄) summed directly (not
// S_gg − S_xg²/S_xx, which cancels when the fit is close). It agrees with
// the QR to rounding; the scan only picks the bracket that golden_section
// and polish_root (through solve_at) then refine. Degenerate or overflowing
// columns go to solve_at. `xp`: scratch of the series' size.
double scan_sum_of_squares(const Scaled& sp, double p, std::vector<double>& xp) {
  const auto n = static_cast<std::size_t>(sp.x.size());
  double sw = 0, sx = 0, sg = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    xp[i] = std::exp(p * sp.log_x(k));
    sw += sp.w(k);
    sx += sp.w(k) * xp[i];
    sg += sp.w(k) * sp.g(k);
  }
  const double xm = sx / sw, gm = sg / sw;
  double sxx = 0, sxg = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const double dx = xp[i] - xm;
    sxx += sp.w(k) * dx * dx;
    sxg += sp.w(k) * dx * (sp.g(k) - gm);
  }
  if (!(sxx > 0) || !std::isfinite(sxx) || !std::isfinite(sxg)) return solve_at(sp, p).S;
  const double b = sxg / sxx;
  double S = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const double r = (sp.g(k) - gm) - b * (xp[i] - xm);
    S += sp.w(k) * r * r;
  }
  return std::isfinite(S) ? S : solve_at(sp, p).S;
}

// dS/dp at the optimal (a, b) for this p (envelope theorem).
double slope(const Scaled& sp, const AtP& at) {
  return -2.0 * at.b *
         (sp.w.array() * at.r.array() * at.xp.array() * sp.log_x.array()).sum();
}

// Golden-section search for a minimum of S on [lo, hi].
double golden_section(const Scaled& sp, double lo, double hi) {
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = hi - inv_phi * (hi - lo), d = lo + inv_phi * (hi - lo);
  double Sc = solve_at(sp, c).S, Sd = solve_at(sp, d).S;
  for (int it = 0; it < 200 && hi - lo > 1e-11 * std::max(1.0, std::fabs(lo)); ++it) {
    if (Sc <= Sd) {
      hi = d;
      d = c;
      Sd = Sc;
      c = hi - inv_phi * (hi - lo);
      Sc = solve_at(sp, c).S;
    } else {
      lo = c;
      c = d;
      Sc = Sd;
      d = lo + inv_phi * (hi - lo);
      Sd = solve_at(sp, d).S;
    }
  }
  return Sc <= Sd ? c : d;
}

// Bisection on the sign of dS/dp inside [lo, hi] when it goes from − to +.
// Returns `guess` if there is no such sign change.
double polish_root(const Scaled& sp, double lo, double hi, double guess) {
  double g_lo = slope(sp, solve_at(sp, lo)), g_hi = slope(sp, solve_at(sp, hi));
  if (!(g_lo < 0 && g_hi > 0)) return guess;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // interval at machine resolution
    const double g_mid = slope(sp, solve_at(sp, mid));
    if (g_mid == 0) return mid;
    (g_mid < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Scan points of one sign, |p| increasing from p_min to p_max.
std::vector<double> scan_points(const PowerSearch& search, double sign) {
  const int n = std::max(search.points_per_side, 3);
  std::vector<double> p(static_cast<std::size_t>(n));
  const double l0 = std::log(search.p_min), l1 = std::log(search.p_max);
  for (int j = 0; j < n; ++j)
    p[static_cast<std::size_t>(j)] = sign * std::exp(l0 + (l1 - l0) * j / (n - 1));
  p.front() = sign * search.p_min;
  p.back() = sign * search.p_max;
  return p;
}

}  // namespace

PowerLawFit fit_power_law(const Series& s, const std::vector<double>& w, const PowerSearch& search) {
  const Scaled sp = scale_problem(s, w);

  // 1. Dense scan of both signs; keep the global minimum of S.
  double best_sign = 1.0;
  std::size_t best_k = 0;
  double best_S = std::numeric_limits<double>::infinity();
  std::vector<double> xp(s.size());
  for (double sign : {1.0, -1.0}) {
    const auto pts = scan_points(search, sign);
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const double S = scan_sum_of_squares(sp, pts[k], xp);
      if (S < best_S) {
        best_S = S;
        best_k = k;
        best_sign = sign;
      }
    }
  }
  const std::vector<double> best_side = scan_points(search, best_sign);

  // 2. Refine inside the neighbouring scan points.
  const std::size_t last = best_side.size() - 1;
  double lo = best_side[best_k == 0 ? 0 : best_k - 1];
  double hi = best_side[std::min(best_k + 1, last)];
  if (lo > hi) std::swap(lo, hi);
  double p = golden_section(sp, lo, hi);
  const double width = std::max(1e-6 * std::fabs(p), 1e-9);
  p = polish_root(sp, std::max(lo, p - width), std::min(hi, p + width), p);

  // 3. A minimum on a range boundary: p not found; report the boundary fit.
  PowerLawFit out;
  out.p_found = true;
  for (double boundary : {best_side.front(), best_side.back()}) {
    if (std::fabs(p - boundary) <= 1e-9 * std::fabs(boundary)) {
      p = boundary;
      out.p_found = false;
    }
  }

  const AtP at = solve_at(sp, p);
  out.p = p;
  out.f0 = sp.f_ref + sp.f_scale * at.a;
  out.c = sp.f_scale * at.b * std::pow(sp.h_max, -p);
  const Eigen::VectorXd r = sp.f_scale * at.r;
  out.sigma = fit_standard_deviation(r, sp.w, 3);
  out.sum_of_squares = weighted_sum_of_squares(r, sp.w);
  out.fhat.resize(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    out.fhat[i] = sp.f_ref + sp.f_scale * (at.a + at.b * at.xp(static_cast<Eigen::Index>(i)));
  return out;
}

double power_law_profile(const Series& s, const std::vector<double>& w, double p) {
  const Scaled sp = scale_problem(s, w);
  return sp.f_scale * sp.f_scale * solve_at(sp, p).S;
}

double power_law_scan_profile(const Series& s, const std::vector<double>& w, double p) {
  const Scaled sp = scale_problem(s, w);
  std::vector<double> xp(s.size());
  return sp.f_scale * sp.f_scale * scan_sum_of_squares(sp, p, xp);
}

}  // namespace gridfree
