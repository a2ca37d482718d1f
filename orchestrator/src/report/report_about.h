// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed "about this case" paragraphs of the report, chosen by the particle
// generator of the study's cases (docs/REPORTS.md). Plain text; each
// renderer escapes it.
#pragma once

#include <string>
#include <vector>

namespace gridfree {

struct AboutSection {
  std::string title;
  std::vector<std::string> paragraphs;
};

// One section per known generator kind among `kinds` (duplicates ignored).
std::vector<AboutSection> about_sections(const std::vector<std::string>& kinds);

}  // namespace gridfree
