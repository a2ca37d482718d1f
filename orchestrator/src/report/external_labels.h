// SPDX-License-Identifier: GPL-3.0-or-later
// How reports name an external case's quantity and its h (docs/EXTERNAL.md
// "The study"), from the study definition: "kinetic_energy: mean kinetic
// energy [m^2/s^2]" instead of DP*, "h = 1 / N" instead of Δ*.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "report/report_data.h"
#include "study/study.h"

namespace gridfree {

// "name: description [units]" (description and units left out when empty).
std::string external_quantity_label(const std::string& name, const std::string& description,
                                    const std::string& units);

// The meaning of h from the case's "h": "h = 1 / N", or
// "h = (V / cells)^(1/2), cells = N * N, V = 0.01".
std::string external_h_label(const nlohmann::json& h);

// Sets sd's quantity, quantity_label and h_label for an external series.
void label_external_series(const nlohmann::json& definition, const SeriesKey& key, SeriesData& sd);

}  // namespace gridfree
