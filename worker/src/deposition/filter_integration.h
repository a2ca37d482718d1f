// SPDX-License-Identifier: GPL-3.0-or-later
// The names of the filter integrations (numerics.deposition.integration,
// docs/TRANSFER.md) — the one list the job parser, the job JSON and the
// orchestrator's study factors read:
//
//   "steps"     backward-Euler steps of the diffusion equation
//   "exact"     the semi-discrete diffusion solved exactly by transforms
//   "gaussian"  the sampled Gaussian of variance 2ν_i, applied by transforms
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "deposition/filter.h"

namespace gridfree {

struct FilterIntegrationName {
  std::string_view name;
  FilterIntegration value;
};

const std::array<FilterIntegrationName, 3>& filter_integration_names();
std::string_view filter_integration_name(FilterIntegration integration);
std::optional<FilterIntegration> parse_filter_integration(std::string_view name);

}  // namespace gridfree
