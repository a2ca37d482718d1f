// SPDX-License-Identifier: GPL-3.0-or-later
// Smooth analytic fields and their derivatives, for manufactured solutions.
//
// Derivatives are taken by 6th-order central differences of the analytic
// function with a fixed small step (h = 1e-3 of the box): the truncation
// error (~h^6 k^7 ≈ 1e-13 for the wave numbers used) and round-off (~1e-16/h
// per derivative, ~1e-10 for second derivatives) are independent of the
// grid under test and far below the discretization errors measured (≥ 1e-6),
// so they cannot bias the observed order.
#pragma once

#include <array>
#include <functional>

namespace gridfree {

using Point3 = std::array<double, 3>;
using ScalarFn = std::function<double(const Point3&)>;

// ∂f/∂x_axis at x.
double partial(const ScalarFn& f, const Point3& x, int axis, double step);

// ∂²f/∂x_a∂x_b at x.
double partial2(const ScalarFn& f, const Point3& x, int a, int b, double step);

}  // namespace gridfree
