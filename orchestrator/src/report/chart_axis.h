// SPDX-License-Identifier: GPL-3.0-or-later
// Axis ranges and tick values for the SVG charts.
//
// Linear axes: ticks at "nice" steps s = m·10^k, m ∈ {1, 2, 5}, the step
// closest to span/(target−1) from above; the range is widened outward to
// whole steps. Log axes: the range is widened to whole decades; ticks at
// 10^k (every decade, or every 2nd/3rd when there are many), or at
// {1, 2, 5}·10^k when the data span at most two decades. A value maps to a
// pixel by linear interpolation of v (linear) or log10 v (log).
#pragma once

#include <string>
#include <vector>

namespace gridfree {

enum class AxisScale { linear, log };

struct AxisTicks {
  double lo = 0, hi = 1;          // the axis range (tick-aligned)
  std::vector<double> major;      // labelled ticks, ascending, within [lo, hi]
  std::vector<double> minor;      // unlabelled ticks (log axes: 2..9·10^k)
  double step = 0;                // linear: tick step; log: 0
};

// The nice step ≥ raw: 1, 2 or 5 times a power of ten.
double nice_step(double raw);

// Linear ticks covering [data_lo, data_hi] with about `target` labels.
// A degenerate range (lo == hi) is widened around the value first.
AxisTicks linear_ticks(double data_lo, double data_hi, int target = 6);

// Log ticks covering [data_lo, data_hi]; both must be > 0 (otherwise the
// range falls back to [1, 10]).
AxisTicks log_ticks(double data_lo, double data_hi);

// The axis rule of the report: log when the data are positive and span more
// than a decade (hi/lo > 10), linear otherwise.
AxisScale scale_for_span(double data_lo, double data_hi);

// Label for a tick: decimals from the linear step (0.2 → "1158.4"), axes
// reaching 10⁵ or more as m×10ᵏ with the axis' exponent ("2.5×10⁶"); on log
// axes plain decimals for 1e-4 ≤ v < 1e4 ("0.0002", "1000"), otherwise
// 10⁻⁵ or 2×10⁵.
std::string format_tick(double value, const AxisTicks& ticks, AxisScale scale);

// Maps data values to pixels along one axis.
struct AxisMap {
  AxisScale scale = AxisScale::linear;
  double lo = 0, hi = 1;            // data range
  double pixel_lo = 0, pixel_hi = 1;  // pixels of lo and hi (y axes: pixel_lo > pixel_hi)
  double operator()(double value) const;
  bool contains(double value) const;  // within [lo, hi] (tiny tolerance)
};

}  // namespace gridfree
