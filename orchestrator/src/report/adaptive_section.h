// SPDX-License-Identifier: GPL-3.0-or-later
// The report's "Adaptive grids" section: every decision of the study's
// adaptive series (sched/adaptive_series.h) in order, as written to the
// events table — why each grid was added and where and why each series
// stopped, with the compute not spent. Empty for studies with a grid list.
#pragma once

#include <string>
#include <vector>

namespace gridfree {

std::string adaptive_section_markdown(const std::vector<std::string>& decisions);
std::string adaptive_section_html(const std::vector<std::string>& decisions);

}  // namespace gridfree
