// SPDX-License-Identifier: GPL-3.0-or-later
// Drag-law registry and dispatch (PHYSICS.md §4): names, references and
// fitted ranges of the six laws, and drag_coefficient() = D with β = ε_s D.
#include "drag/drag_law.h"

#include "drag/drag_laws_detail.h"

namespace gridfree {

double drag_coefficient(DragLaw law, const DragState& s) {
  switch (law) {
    case DragLaw::kWenYu: return drag_detail::wen_yu(s);
    case DragLaw::kGidaspow: return drag_detail::gidaspow(s);
    case DragLaw::kGidaspowBlend: return drag_detail::gidaspow_blend(s);
    case DragLaw::kBvk: return drag_detail::bvk(s);
    case DragLaw::kHkl: return drag_detail::hkl(s);
    case DragLaw::kSyamlalObrien: return drag_detail::syamlal_obrien(s);
  }
  return 0.0;  // unreachable: every enumerator is handled above
}

const std::vector<DragLawInfo>& drag_laws() {
  static const std::vector<DragLawInfo> table = {
      {DragLaw::kBvk, "bvk",
       "Beetstra, van der Hoef & Kuipers, AIChE J. 53 (2007) 489-501; MFiX DRAG_BVK",
       "lattice-Boltzmann fits for monodisperse arrays, 0.1 <= eps_s <= 0.6, Re_s <= 1000"},
      {DragLaw::kGidaspow, "gidaspow",
       "Ding & Gidaspow, AIChE J. 36 (1990) 523-538 (Ergun 1952 + Wen & Yu 1966); MFiX DRAG_GIDASPOW",
       "Ergun for packed beds eps_g <= 0.8, Wen & Yu for eps_g > 0.8; discontinuous at 0.8"},
      {DragLaw::kGidaspowBlend, "gidaspow_blend",
       "Lathouwers & Bellan, Proc. 2000 U.S. DOE Hydrogen Program Review, NREL/CP-570-28890; "
       "MFiX DRAG_GIDASPOW_BLEND",
       "as gidaspow, with an arctan blend of width ~0.01 in eps_g around 0.8"},
      {DragLaw::kWenYu, "wen_yu",
       "Wen & Yu, Chem. Eng. Prog. Symp. Ser. 62 (1966) 100-111; MFiX DRAG_WEN_YU",
       "dilute suspensions, eps_g > 0.8; C_d = 0.44 above Re_s = 1000"},
      {DragLaw::kHkl, "hkl",
       "Hill, Koch & Ladd, J. Fluid Mech. 448 (2001) 213-241, 243-278; extended by Benyahia, "
       "Syamlal & O'Brien, Powder Technol. 162 (2006) 166-174; MFiX DRAG_KOCH_HILL",
       "lattice-Boltzmann fits, eps_s up to ~0.6, Re_s up to ~100 (extension to all Re, eps_s)"},
      {DragLaw::kSyamlalObrien, "syamlal_obrien",
       "Syamlal & O'Brien, Int. J. Multiphase Flow 14 (1988) 473-481; MFiX DRAG_SYAM_OBRIEN "
       "(c1 = 0.8, d1 = 2.65)",
       "terminal-velocity correlation of Richardson & Zaki / Garside & Al-Dibouni, all eps_g"},
  };
  return table;
}

std::optional<DragLaw> drag_law_from_name(std::string_view name) {
  for (const auto& info : drag_laws())
    if (info.name == name) return info.law;
  return std::nullopt;
}

std::string_view drag_law_name(DragLaw law) {
  for (const auto& info : drag_laws())
    if (info.law == law) return info.name;
  return "unknown";
}

std::string drag_law_names() {
  std::string out;
  for (const auto& info : drag_laws()) {
    if (!out.empty()) out += ", ";
    out += info.name;
  }
  return out;
}

}  // namespace gridfree
