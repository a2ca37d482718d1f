// SPDX-License-Identifier: GPL-3.0-or-later
// Sampled-Gaussian symbol (gaussian_symbol.h): a truncated theta series,
// summed in frequency or in space, whichever converges faster.
#include "deposition/gaussian_symbol.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gridfree {
namespace {

constexpr double kTail = 1e-18;  // stop when a term is below this fraction of the first

// Σ_j exp(−a(ω + 2πj)²), ω ∈ [0, π] (terms in increasing distance from ω).
double frequency_sum(double omega, double a) {
  const double two_pi = 2 * std::numbers::pi;
  double sum = std::exp(-a * omega * omega);
  const double first = std::max(sum, std::exp(-a * (omega - two_pi) * (omega - two_pi)));
  for (int j = 1;; ++j) {
    const double lo = std::exp(-a * (omega - two_pi * j) * (omega - two_pi * j));
    const double hi = std::exp(-a * (omega + two_pi * j) * (omega + two_pi * j));
    sum += lo + hi;
    if (lo < kTail * first) return sum;
  }
}

// Σ_m exp(−m²/(4a)) cos(mω).
double spatial_sum(double omega, double a) {
  double sum = 1.0;
  for (int m = 1;; ++m) {
    const double w = std::exp(-double(m) * m / (4 * a));
    sum += 2 * w * std::cos(m * omega);
    if (w < kTail) return sum;
  }
}

}  // namespace

double sampled_gaussian_symbol(double omega, double s_over_h) {
  if (!(s_over_h >= 0) || !std::isfinite(omega)) throw std::invalid_argument("sampled_gaussian_symbol: bad argument");
  if (s_over_h == 0) return 1.0;
  // Reduce ω to [0, π]: ĝ is even and 2π-periodic.
  const double two_pi = 2 * std::numbers::pi;
  double w = std::fmod(std::fabs(omega), two_pi);
  if (w > std::numbers::pi) w = two_pi - w;
  const double a = s_over_h * s_over_h / 2;
  if (a >= 1 / two_pi) return frequency_sum(w, a) / frequency_sum(0.0, a);
  return spatial_sum(w, a) / spatial_sum(0.0, a);
}

std::vector<double> gaussian_axis_factors(int n, double h, double variance, bool periodic) {
  std::vector<double> f(std::size_t(n), 1.0);
  const double scale = periodic ? n : 2.0 * n;
  const double s_over_h = variance > 0 ? std::sqrt(variance) / h : 0.0;
  for (int k = 0; k < n; ++k) {
    const double omega = periodic ? 2 * std::numbers::pi * k / n : std::numbers::pi * k / n;
    f[std::size_t(k)] = sampled_gaussian_symbol(omega, s_over_h) / scale;
  }
  return f;
}

double sampled_gaussian_variance_h2(double s_over_h) {
  if (!(s_over_h > 0)) return 0.0;
  const double a = s_over_h * s_over_h / 2;
  double s0 = 1.0, s2 = 0.0;
  for (int m = 1;; ++m) {
    const double w = std::exp(-double(m) * m / (4 * a));
    s0 += 2 * w;
    s2 += 2 * w * double(m) * m;
    if (w * m * m < kTail * s2) return s2 / s0;
  }
}

}  // namespace gridfree
