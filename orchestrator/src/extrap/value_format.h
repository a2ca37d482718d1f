// SPDX-License-Identifier: GPL-3.0-or-later
// The one number formatter of what gridfree prints for people: the console
// (run, status, extrapolate) and the report (HTML, Markdown, charts) print a
// value and its uncertainty with the digits the uncertainty supports, a cell
// size with one fixed precision, and percentages in one notation
// (docs/DESIGN.md "Printed digits"). Machine-readable output (CSV, JSON)
// keeps full precision and does not use it.
//
//   value ± U   U rounded to two significant digits, the value to the same
//               decimal place: 1015.855 ± 1.4637 → "1015.9 ± 1.5";
//               52 134 ± 270 → "52130 ± 270"; 0.003 ± 25 → "0 ± 25".
//               Magnitudes ≥ 1e9, or a U below 1e-6 (exponent < −7), share
//               one power of ten:
//               "(1.2345 ± 0.0031)e-12".
//   U = 0       "± 0" after the value with `digits` significant digits.
//   U absent, negative or not finite: the value alone, `digits` significant.
//   value NaN/±inf: "nan", "inf", "-inf" (never rounded to a number).
//
// Locale-independent: always '.' as the decimal mark; "-0" is printed "0".
#pragma once

#include <optional>
#include <string>

namespace gridfree {

// Decimal exponent of U's second significant digit after rounding U to two
// significant digits: U = 1.37 → −1, 0.0996 → −2 (U becomes 0.10), 37 → 0,
// 370 → 1. Empty for U absent, ≤ 0 or not finite.
std::optional<int> uncertainty_exponent(const std::optional<double>& u);

// `value` rounded to a multiple of 10^exponent, printed without exponent
// notation unless its magnitude is ≥ 1e9 or the exponent < −7.
std::string format_at_exponent(double value, int exponent);

// "value ± U" as described above.
std::string format_value_u(double value, const std::optional<double>& u, int digits = 6);

// The value part alone, to the decimal place U supports ("1015.9" for
// U = 1.4637): a value quoted beside the one U belongs to (f0 next to
// f₁ ± U₁; the verdict's "f0 lies 1.1 above the largest value 1015.9").
std::string format_value_for_u(double value, const std::optional<double>& u, int digits = 6);

// `value` rounded to the decimal place U supports (unchanged without a usable
// U): a difference of two quoted values is taken between the rounded ones,
// so the sentence's arithmetic holds in the printed digits.
double rounded_for_u(double value, const std::optional<double>& u);

// The U whose digits f0 is printed with: U₀ when it is usable (finite, > 0),
// else the finest grid's U₁ (report headline, console and verdict agree).
std::optional<double> f0_digits_u(const std::optional<double>& u0, const std::optional<double>& u1);

// The console's line for one extrapolation (`run` as a series finishes,
// `extrapolate` on stderr): "verdict converged: f0 = 1017.0 ± 1.5, finest
// f1 = 1015.9 ± 1.5 (RDE 0.149%)" — f0 ± U₀ (without U₀, f0 to U₁'s digits),
// f₁ ± U₁ of the finest grid; absent numbers are left out.
std::string verdict_line(const std::string& verdict, const std::optional<double>& f0, const std::optional<double>& u0,
                         const std::optional<double>& f1, const std::optional<double>& u1,
                         const std::optional<double>& rde);

// A cell size (Δ* or h) everywhere it is printed for people: 4 significant
// digits ("1.295", "0.7861", "12.5").
std::string format_cell_size(double h);

// A number that is not a value of the quantity (an observed order p, a
// ratio, a factor of safety, a rule's threshold): `digits` significant
// digits, trailing zeros dropped, locale-independent ("1.601", "0.5").
std::string format_significant(double v, int digits = 4);

// value·100 with `digits` significant digits and a '%', never in exponent
// notation: 0.0938 → "9.38%", 9.38e-8 → "0.00000938%"; 0 → "0%".
std::string format_percent_fixed(double fraction, int digits = 3);

}  // namespace gridfree
