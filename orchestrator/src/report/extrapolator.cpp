// SPDX-License-Identifier: GPL-3.0-or-later
// library_extrapolator: calls the extrapolation library (extrap/) and returns
// its contract JSON. This is the only report file that includes extrap/
// headers, so the rest of the report depends on the JSON form alone.
#include "report/extrapolator.h"

#include <cstdio>

#include "extrap/coverage_record.h"
#include "extrap/extrapolation.h"

namespace gridfree {

Extrapolator library_extrapolator(const ExtrapolatorSettings& settings) {
  return [settings](const std::vector<double>& h, const std::vector<double>& f) {
    // Bad settings are reported per series (the caller records the error).
    ExtrapolationOptions options;
    options.method = parse_method(settings.method, "/extrapolation/method");
    options.p_low = settings.p_low;
    options.p_high = settings.p_high;
    options.weights = settings.weights == "uniform" ? Weighting::kUniform : Weighting::kInverseH;
    options.expected_order = settings.expected_order;
    options.h_symbol = settings.h_symbol;
    validate_options(options);
    return to_json(extrapolate(h, f, options));
  };
}

std::string measured_coverage_line(const std::string& method, bool order_declared) {
  ExtrapolationMethod m;
  try {
    m = parse_method(method, "method");
  } catch (const std::exception&) {
    return {};
  }
  const MeasuredCoverage c = measured_coverage(m, order_declared);
  std::string out = c.method + (order_declared ? " (formal order declared)" : " (no formal order declared)") +
                    ": f₁ ± U₁ covered the reference in";
  for (std::size_t i = 0; i < c.classes.size(); ++i) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s %.0f %% of %s", i ? "," : "", 100 * c.classes[i].u1,
                  c.classes[i].verdict.c_str());
    out += buf;
  }
  out += " windows of " + c.corpus + " (" + c.measured + ")";
  if (!c.shortfall.empty()) out += "; short of 95 %: " + c.shortfall;
  return out;
}

}  // namespace gridfree
