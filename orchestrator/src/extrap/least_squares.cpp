// SPDX-License-Identifier: GPL-3.0-or-later
// Weighted least squares by QR of the √w-scaled system (see least_squares.h).
#include "extrap/least_squares.h"

#include <cmath>
#include <limits>

namespace gridfree {

LinearFit weighted_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& y,
                                 const Eigen::VectorXd& w) {
  const Eigen::VectorXd sw = w.cwiseSqrt();
  Eigen::MatrixXd As = sw.asDiagonal() * A;
  const Eigen::VectorXd ys = sw.cwiseProduct(y);

  // Column equilibration: solve for z = D x with unit-norm columns As D^{-1}.
  Eigen::VectorXd scale(A.cols());
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    const double norm = As.col(j).norm();
    scale(j) = norm > 0 ? norm : 1.0;
    As.col(j) /= scale(j);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(As);
  const Eigen::VectorXd z = qr.solve(ys);

  LinearFit fit;
  fit.x = z.cwiseQuotient(scale);
  fit.residuals = y - A * fit.x;
  fit.sum_of_squares = weighted_sum_of_squares(fit.residuals, w);
  return fit;
}

double weighted_sum_of_squares(const Eigen::VectorXd& r, const Eigen::VectorXd& w) {
  return (w.array() * r.array().square()).sum();
}

double fit_standard_deviation(const Eigen::VectorXd& r, const Eigen::VectorXd& w, int parameters) {
  const auto n = r.size();
  if (n <= parameters) return std::numeric_limits<double>::quiet_NaN();
  const double s = static_cast<double>(n) * weighted_sum_of_squares(r, w);
  return std::sqrt(s / static_cast<double>(n - parameters));
}

}  // namespace gridfree
