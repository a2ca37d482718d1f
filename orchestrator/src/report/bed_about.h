// SPDX-License-Identifier: GPL-3.0-or-later
// "About this case: bed structure" (docs/REPORTS.md): one line per case, or
// per ensemble with the range over its instances, from the "bed" summary of
// the case's results (docs/INTERFACE.md §2, store/store_beds.h), with the
// rule for reading it. Plain text; each renderer escapes it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/report_about.h"

namespace gridfree {

inline constexpr double kOrderedBedPeak = 0.05;  // core S/N flagged ordered when a summary lacks `ordered` (worker: particles/bed_summary.h)

// The section, or nothing when no case has a bed summary. `cases`: every
// case of the study in report order (duplicates ignored); `ensembles`:
// ensemble name → its instance cases.
std::optional<AboutSection> bed_about_section(const std::vector<std::string>& cases,
                                              const std::map<std::string, nlohmann::json>& beds,
                                              const std::map<std::string, std::vector<std::string>>& ensembles);

// The line of one case (or of an ensemble's instances, as ranges) without
// its "name: " prefix.
std::string bed_line(const std::vector<const nlohmann::json*>& instances);

}  // namespace gridfree
