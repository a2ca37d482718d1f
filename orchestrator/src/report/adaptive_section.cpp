// SPDX-License-Identifier: GPL-3.0-or-later
// The "Adaptive grids" report section (report/adaptive_section.h).
#include "report/adaptive_section.h"

#include "report/text_format.h"

namespace gridfree {
namespace {

constexpr const char* kNote =
    "Each series ran coarse to fine on the ladder h_k = coarsest/ratio^k of its cell size and was extrapolated "
    "after every grid from the fourth on; it stopped when its verdict was converged and its finest grid's RDE met "
    "the target, or ended 'target not reached' at a cap or at the finest grid the study allows "
    "(docs/EXTRAPOLATION.md, \"Adaptive series\"). "
    "When the fit of all its grids was not converged, the finest grids (at least five) were fitted instead and "
    "the decision names them; a stopped series' f0, U and verdict are those of the fit its last decision used. "
    "Savings are the cost model's estimates, scaled by the series' measured times, of the grids not run.";

}  // namespace

std::string adaptive_section_markdown(const std::vector<std::string>& decisions) {
  if (decisions.empty()) return "";
  std::string out = "## Adaptive grids\n\n" + std::string(kNote) + "\n\n";
  for (const auto& d : decisions) out += "- " + d + "\n";
  return out + "\n";
}

std::string adaptive_section_html(const std::vector<std::string>& decisions) {
  if (decisions.empty()) return "";
  std::string out = "<h2 id=\"adaptive\">Adaptive grids</h2>\n<p class=\"note\">" + xml_escape(kNote) + "</p>\n<ul>\n";
  for (const auto& d : decisions) out += "<li>" + xml_escape(d) + "</li>\n";
  return out + "</ul>\n";
}

}  // namespace gridfree
