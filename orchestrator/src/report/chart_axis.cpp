// SPDX-License-Identifier: GPL-3.0-or-later
// Tick generation and value→pixel mapping (see chart_axis.h).
#include "report/chart_axis.h"

#include <algorithm>
#include <cmath>

#include "report/text_format.h"

namespace gridfree {

double nice_step(double raw) {
  if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    // 1e-9 relative slack so that an exact 0.2 is not bumped to 0.5.
    if (m * decade >= raw * (1 - 1e-9)) return m * decade;
  }
  return 10.0 * decade;
}

AxisTicks linear_ticks(double data_lo, double data_hi, int target) {
  if (data_lo > data_hi) std::swap(data_lo, data_hi);
  if (!std::isfinite(data_lo) || !std::isfinite(data_hi)) {
    data_lo = 0;
    data_hi = 1;
  }
  if (data_hi - data_lo <= 1e-12 * std::max(std::abs(data_lo), std::abs(data_hi))) {
    const double pad = data_lo != 0 ? 0.05 * std::abs(data_lo) : 1.0;
    data_lo -= pad;
    data_hi += pad;
  }
  target = std::max(target, 2);
  AxisTicks ticks;
  ticks.step = nice_step((data_hi - data_lo) / (target - 1));
  const double first = std::floor(data_lo / ticks.step + 1e-9) * ticks.step;
  const double last = std::ceil(data_hi / ticks.step - 1e-9) * ticks.step;
  ticks.lo = std::min(first, data_lo);
  ticks.hi = std::max(last, data_hi);
  const long count = std::lround((last - first) / ticks.step);
  for (long i = 0; i <= count; ++i) {
    double value = first + static_cast<double>(i) * ticks.step;
    if (std::abs(value) < 1e-9 * ticks.step) value = 0;  // no "-0" from rounding
    ticks.major.push_back(value);
  }
  return ticks;
}

AxisTicks log_ticks(double data_lo, double data_hi) {
  if (data_lo > data_hi) std::swap(data_lo, data_hi);
  if (!(data_lo > 0) || !std::isfinite(data_lo) || !std::isfinite(data_hi)) {
    data_lo = 1;
    data_hi = 10;
  }
  int k_lo = static_cast<int>(std::floor(std::log10(data_lo) + 1e-12));
  int k_hi = static_cast<int>(std::ceil(std::log10(data_hi) - 1e-12));
  if (k_hi <= k_lo) k_hi = k_lo + 1;
  AxisTicks ticks;
  ticks.lo = std::pow(10.0, k_lo);
  ticks.hi = std::pow(10.0, k_hi);
  const int decades = k_hi - k_lo;
  const int every = decades > 16 ? 3 : decades > 8 ? 2 : 1;
  for (int k = k_lo; k <= k_hi; ++k) {
    const double decade = std::pow(10.0, k);
    if ((k - k_lo) % every == 0) ticks.major.push_back(decade);
    if (k == k_hi) break;
    for (int m = 2; m <= 9; ++m) {
      if (decades <= 2 && (m == 2 || m == 5)) {
        ticks.major.push_back(m * decade);
      } else {
        ticks.minor.push_back(m * decade);
      }
    }
  }
  std::sort(ticks.major.begin(), ticks.major.end());
  return ticks;
}

AxisScale scale_for_span(double data_lo, double data_hi) {
  if (data_lo > data_hi) std::swap(data_lo, data_hi);
  const bool positive = data_lo > 0 && std::isfinite(data_hi);
  return positive && data_hi > 10.0 * data_lo ? AxisScale::log : AxisScale::linear;
}

namespace {

std::string superscript_integer(int k) {
  static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = k < 0 ? "⁻" : "";
  const std::string plain = std::to_string(std::abs(k));
  for (char ch : plain) out += digits[ch - '0'];
  return out;
}

}  // namespace

std::string format_tick(double value, const AxisTicks& ticks, AxisScale scale) {
  if (scale == AxisScale::log) {
    // Log ticks are m·10^k with m in 1..9: plain decimals in [1e-4, 1e4),
    // otherwise 10ᵏ or m×10ᵏ.
    const int k = static_cast<int>(std::floor(std::log10(value) + 1e-9));
    const long mantissa = std::lround(value / std::pow(10.0, k));
    if (k < -4 || k >= 4) {
      std::string out = mantissa == 1 ? std::string() : std::to_string(mantissa) + "×";
      out += "10";
      out += superscript_integer(k);
      return out;
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", std::max(0, -k), value);
    return buffer;
  }
  const double magnitude = std::max(std::abs(ticks.lo), std::abs(ticks.hi));
  if (value == 0) return "0";
  if (magnitude < 1e-4) return format_g(value, 3);
  if (magnitude >= 1e5) {
    // m×10ᵏ with the axis' exponent: 4000000 → "4×10⁶", 2500000 → "2.5×10⁶".
    const int k = static_cast<int>(std::floor(std::log10(magnitude) + 1e-9));
    const double power = std::pow(10.0, k);
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(ticks.step / power) + 1e-9)));
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value / power);
    return buffer + std::string("×10") + superscript_integer(k);
  }
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(ticks.step) + 1e-9)));
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string out = buffer;
  for (char& ch : out) {
    if (ch == ',') ch = '.';
  }
  return out;
}

double AxisMap::operator()(double value) const {
  double t = 0;
  if (scale == AxisScale::log) {
    t = (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
  } else {
    t = (value - lo) / (hi - lo);
  }
  return pixel_lo + t * (pixel_hi - pixel_lo);
}

bool AxisMap::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (scale == AxisScale::log && !(value > 0)) return false;
  const double slack = 1e-9 * (std::abs(hi - lo) + std::abs(hi));
  return value >= lo - slack && value <= hi + slack;
}

}  // namespace gridfree
