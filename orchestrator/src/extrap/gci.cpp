// SPDX-License-Identifier: GPL-3.0-or-later
// Celik et al. (2008) three-grid GCI for each consecutive triplet (see gci.h).
#include "extrap/gci.h"

#include <algorithm>
#include <cmath>

namespace gridfree {
namespace {

// Fixed-point iteration of C08 eq. 5: p ← |ln|ε32/ε21| + q(p)| / ln r21.
// Converged when successive iterates agree to 1e-13 (relative for p > 1).
std::optional<double> apparent_order(double r21, double r32, double e21, double e32, int& iterations) {
  const double s = (e32 / e21) > 0 ? 1.0 : -1.0;
  const double log_ratio = std::log(std::fabs(e32 / e21));
  const double log_r21 = std::log(r21);
  double p = std::fabs(log_ratio) / log_r21;  // q = 0
  for (iterations = 1; iterations <= kGciMaxIterations; ++iterations) {
    const double num = std::pow(r21, p) - s, den = std::pow(r32, p) - s;
    if (!(num > 0 && den > 0) || !std::isfinite(num) || !std::isfinite(den)) return std::nullopt;
    const double q = std::log(num / den);
    const double next = std::fabs(log_ratio + q) / log_r21;
    if (!std::isfinite(next)) return std::nullopt;
    if (std::fabs(next - p) <= 1e-13 * std::max(1.0, p)) return next;
    p = next;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> convergence_type(double r21, double r32, double e21, double e32) {
  if (e21 == 0 || e32 == 0) return std::nullopt;
  const double x = e32 / e21;
  if (x < 0) return std::string("oscillatory");
  return std::string(x > std::log(r32) / std::log(r21) ? "monotone" : "divergent");
}

GciTriplet gci_triplet(const std::array<double, 3>& h, const std::array<double, 3>& f) {
  GciTriplet t;
  t.h = h;
  t.f = f;
  t.r21 = h[1] / h[0];
  t.r32 = h[2] / h[1];
  const double e21 = f[1] - f[0], e32 = f[2] - f[1];
  if (e32 != 0) t.ratio = e21 / e32;
  t.convergence = convergence_type(t.r21, t.r32, e21, e32);
  if (e21 == 0 || e32 == 0) {
    t.status = "zero_difference";
    return t;
  }

  const auto p = apparent_order(t.r21, t.r32, e21, e32, t.iterations);
  if (!p) {
    t.status = "no_convergence_of_order_iteration";
    return t;
  }
  t.p = *p;
  const double rp = std::pow(t.r21, *p);
  if (!std::isfinite(rp)) {
    t.status = "order_overflow";
    return t;
  }
  if (rp - 1.0 <= 0) {
    t.status = "zero_order";
    return t;
  }
  t.f_ext = (rp * f[0] - f[1]) / (rp - 1.0);
  t.gci_fine_abs = 1.25 * std::fabs(f[0] - f[1]) / (rp - 1.0);
  if (*t.f_ext != 0) t.e_ext21 = std::fabs((*t.f_ext - f[0]) / *t.f_ext);
  if (f[0] == 0) {
    t.status = "zero_fine_value";
    return t;
  }
  t.e_a21 = std::fabs((f[0] - f[1]) / f[0]);
  t.gci_fine = 1.25 * *t.e_a21 / (rp - 1.0);
  return t;
}

std::vector<GciTriplet> gci_triplets(const Series& s) {
  std::vector<GciTriplet> out;
  for (std::size_t i = 0; i + 2 < s.size(); ++i)
    out.push_back(gci_triplet({s.h[i], s.h[i + 1], s.h[i + 2]}, {s.f[i], s.f[i + 1], s.f[i + 2]}));
  return out;
}

}  // namespace gridfree
