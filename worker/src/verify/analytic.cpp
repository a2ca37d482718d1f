// SPDX-License-Identifier: GPL-3.0-or-later
#include "verify/analytic.h"

namespace gridfree {

double partial(const ScalarFn& f, const Point3& x, int axis, double step) {
  // f' ≈ [45(f1 − f−1) − 9(f2 − f−2) + (f3 − f−3)] / (60 h)
  auto at = [&](int m) {
    Point3 y = x;
    y[axis] += m * step;
    return f(y);
  };
  return (45.0 * (at(1) - at(-1)) - 9.0 * (at(2) - at(-2)) + (at(3) - at(-3))) / (60.0 * step);
}

double partial2(const ScalarFn& f, const Point3& x, int a, int b, double step) {
  const ScalarFn df = [&](const Point3& y) { return partial(f, y, b, step); };
  return partial(df, x, a, step);
}

}  // namespace gridfree
