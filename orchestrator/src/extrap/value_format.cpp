// SPDX-License-Identifier: GPL-3.0-or-later
// Printed digits of values, uncertainties, cell sizes and percentages (see
// value_format.h).
#include "extrap/value_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridfree {
namespace {

// printf in the C locale whatever LC_NUMERIC says; "-0…" with only zeros
// becomes "0…".
std::string c_printf(const char* format, int precision, double v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, format, precision, v);
  std::string out = buffer;
  for (char& ch : out)
    if (ch == ',') ch = '.';
  if (!out.empty() && out[0] == '-' && out.find_first_of("123456789") == std::string::npos) out.erase(0, 1);
  return out;
}

std::string non_finite(double v) {
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

bool usable_u(const std::optional<double>& u) { return u && std::isfinite(*u) && *u > 0; }

// Exponent notation for a whole "value ± U" when fixed notation would run
// long: huge magnitudes or a U below 1e-6.
bool needs_power(double value, int exponent) { return std::fabs(value) >= 1e9 || exponent < -7; }

}  // namespace

std::optional<int> uncertainty_exponent(const std::optional<double>& u) {
  if (!usable_u(u)) return std::nullopt;
  int e = static_cast<int>(std::floor(std::log10(*u))) - 1;
  // 99.7 rounds to 100 at two digits: then its second digit is one place up.
  if (std::round(*u / std::pow(10.0, e)) >= 100) ++e;
  return e;
}

std::string format_at_exponent(double value, int exponent) {
  if (!std::isfinite(value)) return non_finite(value);
  const double step = std::pow(10.0, exponent);
  const double rounded = std::round(value / step) * step;
  if (needs_power(value, exponent)) {
    const int power = rounded == 0 ? exponent : static_cast<int>(std::floor(std::log10(std::fabs(rounded))));
    return c_printf("%.*f", std::max(0, power - exponent), rounded / std::pow(10.0, power)) + "e" +
           (power < 0 ? "-" : "+") + std::to_string(std::abs(power));
  }
  return c_printf("%.*f", std::max(0, -exponent), rounded);
}

std::string format_value_u(double value, const std::optional<double>& u, int digits) {
  if (!std::isfinite(value)) return non_finite(value);
  if (u && *u == 0) return c_printf("%.*g", digits, value) + " ± 0";
  const auto e = uncertainty_exponent(u);
  if (!e) return c_printf("%.*g", digits, value);
  const double step = std::pow(10.0, *e);
  const double u_rounded = std::round(*u / step) * step;
  if (needs_power(value, *e)) {
    // One power of ten for both: that of the larger of |value| and U.
    const double larger = std::max(std::fabs(std::round(value / step) * step), u_rounded);
    const int power = static_cast<int>(std::floor(std::log10(larger)));
    const double scale = std::pow(10.0, power);
    const int decimals = std::max(0, power - *e);
    return "(" + c_printf("%.*f", decimals, std::round(value / step) * step / scale) + " ± " +
           c_printf("%.*f", decimals, u_rounded / scale) + ")e" + (power < 0 ? "-" : "+") +
           std::to_string(std::abs(power));
  }
  return format_at_exponent(value, *e) + " ± " + c_printf("%.*f", std::max(0, -*e), u_rounded);
}

std::string format_value_for_u(double value, const std::optional<double>& u, int digits) {
  if (!std::isfinite(value)) return non_finite(value);
  const auto e = uncertainty_exponent(u);
  if (!e) return c_printf("%.*g", digits, value);
  return format_at_exponent(value, *e);
}

double rounded_for_u(double value, const std::optional<double>& u) {
  const auto e = uncertainty_exponent(u);
  if (!e || !std::isfinite(value)) return value;
  const double step = std::pow(10.0, *e);
  return std::round(value / step) * step;
}

std::optional<double> f0_digits_u(const std::optional<double>& u0, const std::optional<double>& u1) {
  return usable_u(u0) ? u0 : u1;
}

std::string verdict_line(const std::string& verdict, const std::optional<double>& f0, const std::optional<double>& u0,
                         const std::optional<double>& f1, const std::optional<double>& u1,
                         const std::optional<double>& rde) {
  std::string out = "verdict " + verdict;
  if (f0) out += ": f0 = " + (u0 ? format_value_u(*f0, u0) : format_value_for_u(*f0, u1));
  if (f1 && u1) out += ", finest f1 = " + format_value_u(*f1, u1);
  if (rde) out += " (RDE " + format_percent_fixed(*rde) + ")";
  return out;
}

std::string format_cell_size(double h) {
  if (!std::isfinite(h)) return non_finite(h);
  return c_printf("%.*g", 4, h);
}

std::string format_significant(double v, int digits) {
  if (!std::isfinite(v)) return non_finite(v);
  return c_printf("%.*g", digits, v);
}

std::string format_percent_fixed(double fraction, int digits) {
  const double x = fraction * 100.0;
  if (!std::isfinite(x)) return non_finite(x) + "%";
  if (x == 0) return "0%";
  const int top = digits - 1;  // decimals = digits − 1 − (exponent of x)
  int decimals = std::max(0, top - static_cast<int>(std::floor(std::log10(std::fabs(x)))));
  std::string out = c_printf("%.*f", decimals, x);
  // Rounding can add a digit (99.96 → "100.0"): one decimal fewer then.
  const double shown = std::fabs(std::stod(out));
  if (decimals > 0 && shown != 0 && top - static_cast<int>(std::floor(std::log10(shown))) < decimals)
    out = c_printf("%.*f", --decimals, x);
  return out + "%";
}

}  // namespace gridfree
