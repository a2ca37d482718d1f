// SPDX-License-Identifier: GPL-3.0-or-later
// Filter integration names (filter_integration.h).
#include "deposition/filter_integration.h"

namespace gridfree {

const std::array<FilterIntegrationName, 3>& filter_integration_names() {
  static constexpr std::array<FilterIntegrationName, 3> kNames{{{"steps", FilterIntegration::kSteps},
                                                               {"exact", FilterIntegration::kExact},
                                                               {"gaussian", FilterIntegration::kGaussian}}};
  return kNames;
}

std::string_view filter_integration_name(FilterIntegration integration) {
  for (const auto& n : filter_integration_names())
    if (n.value == integration) return n.name;
  return "unknown";
}

std::optional<FilterIntegration> parse_filter_integration(std::string_view name) {
  for (const auto& n : filter_integration_names())
    if (n.name == name) return n.value;
  return std::nullopt;
}

}  // namespace gridfree
