// SPDX-License-Identifier: GPL-3.0-or-later
// Weighted linear least squares, the building block of every fit in extrap/.
//
//     minimise  S(x) = Σ_i w_i (y_i − (A x)_i)²
//
// solved as the ordinary problem (√W A) x ≈ √W y by column-pivoted Householder
// QR (never the normal equations, whose conditioning is the square). Columns
// are scaled to unit norm first, which QR is not invariant to, so that fits
// with columns like h^p (p = ±10) keep full precision.
//
// The standard deviation of a fit with k parameters on n points, with
// normalised weights (Σ w = 1), is (PHYSICS.md §8; EH14 eqs. 12-13, where the
// unweighted case is w_i = 1/n):
//
//     σ = sqrt( Σ_i n w_i r_i² / (n − k) ),   r_i = y_i − (A x)_i
#pragma once

#include <Eigen/Dense>

namespace gridfree {

struct LinearFit {
  Eigen::VectorXd x;          // coefficients
  Eigen::VectorXd residuals;  // r = y − A x (unweighted)
  double sum_of_squares = 0;  // S = Σ w r²
};

// A is n×k with n ≥ k; w > 0. Rank-deficient A gives the pivoted basic solution.
LinearFit weighted_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& y,
                                 const Eigen::VectorXd& w);

// Σ w_i r_i².
double weighted_sum_of_squares(const Eigen::VectorXd& r, const Eigen::VectorXd& w);

// σ as above; NaN when n ≤ k (no degrees of freedom left).
double fit_standard_deviation(const Eigen::VectorXd& r, const Eigen::VectorXd& w, int parameters);

}  // namespace gridfree
