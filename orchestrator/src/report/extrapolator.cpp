// SPDX-License-Identifier: GPL-3.0-or-later
// library_extrapolator: calls the extrapolation library (extrap/) and returns
// its contract JSON. This is the only report file that includes extrap/
// headers, so the rest of the report depends on the JSON form alone.
#include "report/extrapolator.h"

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
    validate_options(options);
    return to_json(extrapolate(h, f, options));
  };
}

}  // namespace gridfree
