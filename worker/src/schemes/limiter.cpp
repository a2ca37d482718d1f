// SPDX-License-Identifier: GPL-3.0-or-later
// TVD flux limiters ψ(r) and the limited face value (PHYSICS.md §5):
//
//   r   = (φ_C − φ_U)/(φ_D − φ_C),   C the upwind cell of the face,
//   φ_f = φ_C + ½ ψ(r) (φ_D − φ_C),
//
//   fou      ψ = 0                          (first-order upwind)
//   central  ψ = 1                          (linear interpolation, unlimited)
//   minmod   ψ = max(0, min(1, r))
//   van_leer ψ = (r + |r|)/(1 + |r|)
//   muscl    ψ = max(0, min(2r, (1+r)/2, 2)) (van Leer's monotonized central)
//   superbee ψ = max(0, min(1, 2r), min(2, r))
//
// The TVD limiters satisfy 0 ≤ ψ ≤ min(2r, 2), ψ(r ≤ 0) = 0 and ψ(1) = 1;
// all but central are symmetric, ψ(r)/r = ψ(1/r). Every ψ is evaluated so
// that any finite or infinite r gives a finite value (van Leer as 2/(1 + 1/r)
// for r > 1).
#include "schemes/limiter.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

const std::vector<LimiterInfo>& limiters() {
  static const std::vector<LimiterInfo> table = {
      {Limiter::kFou, "fou", "first-order upwind (Courant, Isaacson & Rees 1952)", 1},
      {Limiter::kCentral, "central", "linear interpolation, no limiting (not TVD)", 2},
      {Limiter::kMinmod, "minmod", "Roe, Annu. Rev. Fluid Mech. 18 (1986) 337-365", 2},
      {Limiter::kVanLeer, "van_leer", "van Leer, J. Comput. Phys. 14 (1974) 361-370", 2},
      {Limiter::kMuscl, "muscl",
       "van Leer, J. Comput. Phys. 23 (1977) 276-299 (monotonized central)", 2},
      {Limiter::kSuperbee, "superbee", "Roe, Annu. Rev. Fluid Mech. 18 (1986) 337-365", 2},
  };
  return table;
}

std::optional<Limiter> limiter_from_name(std::string_view name) {
  for (const auto& info : limiters())
    if (info.name == name) return info.limiter;
  return std::nullopt;
}

std::string_view limiter_name(Limiter limiter) {
  for (const auto& info : limiters())
    if (info.limiter == limiter) return info.name;
  return "unknown";
}

std::string limiter_names() {
  std::string out;
  for (const auto& info : limiters()) {
    if (!out.empty()) out += ", ";
    out += info.name;
  }
  return out;
}

}  // namespace gridfree
