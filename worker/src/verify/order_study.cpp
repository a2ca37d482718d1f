// SPDX-License-Identifier: GPL-3.0-or-later
#include "verify/order_study.h"

#include <cmath>
#include <limits>

namespace gridfree {

double observed_order(const std::vector<double>& h, const std::vector<double>& errors) {
  const std::size_t n = errors.size();
  if (n < 2 || h.size() != n) return std::numeric_limits<double>::quiet_NaN();
  return std::log(errors[n - 2] / errors[n - 1]) / std::log(h[n - 2] / h[n - 1]);
}

void finish_study(OrderStudy& s, const std::vector<int>& grids, const std::vector<GridOutcome>& outcomes) {
  for (std::size_t i = 0; i < grids.size() && i < outcomes.size(); ++i) {
    s.grids.push_back(grids[i]);
    s.h.push_back(1.0 / grids[i]);
    s.iterations.push_back(outcomes[i].iterations);
    if (!outcomes[i].failure.empty()) {
      s.failure = outcomes[i].failure;
      s.errors.push_back(std::numeric_limits<double>::quiet_NaN());
      break;
    }
    s.errors.push_back(outcomes[i].error);
  }
  s.observed_order = observed_order(s.h, s.errors);
}

bool OrderStudy::passed() const {
  return failure.empty() && std::isfinite(observed_order) && observed_order >= expected_order - 0.2;
}

nlohmann::json to_json(const OrderStudy& s) {
  nlohmann::json j{{"equation", s.equation},
                   {"scheme", s.scheme},
                   {"norm", s.norm},
                   {"expected_order", s.expected_order},
                   {"grids", s.grids},
                   {"h", s.h},
                   {"errors", s.errors},
                   {"iterations", s.iterations},
                   {"passed", s.passed()}};
  j["observed_order"] = std::isfinite(s.observed_order) ? nlohmann::json(s.observed_order) : nlohmann::json();
  if (!s.failure.empty()) j["failure"] = s.failure;
  return j;
}

}  // namespace gridfree
