// SPDX-License-Identifier: GPL-3.0-or-later
// Iterative-error estimate of a monitored quantity q from its history.
//
// With values spaced w iterations apart at the back of the history,
//   Δ_n = |q_n − q_{n−w}|,  Δ_{n−w} = |q_{n−w} − q_{n−2w}|,  R = Δ_n / Δ_{n−w},
// the remaining change of a geometrically converging sequence is
//   |q_∞ − q_n| ≈ Δ_n R / (1 − R),
// exact when q_n = q_∞ + C ρ^n (then R = ρ^w). Returned relative to |q_n|.
#pragma once

#include <deque>
#include <optional>

namespace gridfree {

// nullopt when the history holds fewer than 2w + 1 values, q_n = 0, or the
// changes do not shrink (R ≥ 1: oscillating, stalled or round-off noise);
// 0 when the last change is exactly 0.
std::optional<double> geometric_iterative_error(const std::deque<double>& history, int window);

}  // namespace gridfree
