// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed-exponent fits f0 + Σ c_k h^{e_k} (see mixed_fit.h).
#include "extrap/mixed_fit.h"

#include <algorithm>
#include <cmath>

#include "extrap/least_squares.h"

namespace gridfree {

FixedOrderFit fit_fixed_orders(const Series& s, const std::vector<double>& w,
                               const std::vector<double>& exponents) {
  const auto n = static_cast<Eigen::Index>(s.size());
  const auto k = static_cast<Eigen::Index>(exponents.size());
  const Eigen::VectorXd wv = Eigen::Map<const Eigen::VectorXd>(w.data(), n);

  // Scaled variables: x = h/h_max, g = (f − f_ref)/f_scale.
  const double h_max = *std::max_element(s.h.begin(), s.h.end());
  double f_ref = 0;
  for (Eigen::Index i = 0; i < n; ++i) f_ref += wv(i) * s.f[static_cast<std::size_t>(i)];
  double spread = 0;
  for (double fi : s.f) spread = std::max(spread, std::fabs(fi - f_ref));
  const double f_scale = spread > 0 ? spread : 1.0;

  Eigen::MatrixXd A(n, k + 1);
  Eigen::VectorXd g(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const double x = s.h[ii] / h_max;
    A(i, 0) = 1.0;
    for (Eigen::Index j = 0; j < k; ++j)
      A(i, j + 1) = std::pow(x, exponents[static_cast<std::size_t>(j)]);
    g(i) = (s.f[ii] - f_ref) / f_scale;
  }
  const LinearFit fit = weighted_least_squares(A, g, wv);

  FixedOrderFit out;
  out.exponents = exponents;
  out.f0 = f_ref + f_scale * fit.x(0);
  for (Eigen::Index j = 0; j < k; ++j) {
    const double e = exponents[static_cast<std::size_t>(j)];
    out.coefficients.push_back(f_scale * fit.x(j + 1) * std::pow(h_max, -e));
  }
  const Eigen::VectorXd r = f_scale * fit.residuals;
  out.sigma = fit_standard_deviation(r, wv, static_cast<int>(k + 1));
  out.fhat.resize(s.size());
  const Eigen::VectorXd model = A * fit.x;
  for (Eigen::Index i = 0; i < n; ++i)
    out.fhat[static_cast<std::size_t>(i)] = f_ref + f_scale * model(i);
  return out;
}

}  // namespace gridfree
