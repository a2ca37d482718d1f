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

double limiter_psi(Limiter limiter, double r) {
  switch (limiter) {
    case Limiter::kFou: return 0.0;
    case Limiter::kCentral: return 1.0;
    case Limiter::kMinmod: return std::max(0.0, std::min(1.0, r));
    case Limiter::kVanLeer:
      if (r <= 0) return 0.0;
      return r > 1 ? 2.0 / (1.0 + 1.0 / r) : 2.0 * r / (1.0 + r);
    case Limiter::kMuscl: return std::max(0.0, std::min({2.0 * r, 0.5 * (1.0 + r), 2.0}));
    case Limiter::kSuperbee: return std::max({0.0, std::min(1.0, 2.0 * r), std::min(2.0, r)});
  }
  return 0.0;  // unreachable: every enumerator is handled above
}

// Convention for a flat downwind difference (φ_D = φ_C): the ratio is taken
// as ±kLargeRatio with the sign of the numerator (0 when φ_U = φ_C too), so
// ψ saturates at its r → ±∞ value. The face value does not depend on it,
// since ψ multiplies φ_D − φ_C = 0. Finite quotients are clamped to the same
// bound, so no overflow to ±inf reaches ψ.
double limiter_ratio(double phi_u, double phi_c, double phi_d) {
  constexpr double kLargeRatio = 1e30;
  const double num = phi_c - phi_u;
  const double den = phi_d - phi_c;
  if (den == 0.0) {
    if (num == 0.0) return 0.0;
    return num > 0 ? kLargeRatio : -kLargeRatio;
  }
  return std::clamp(num / den, -kLargeRatio, kLargeRatio);
}

double limited_face_value(Limiter limiter, double phi_u, double phi_c, double phi_d) {
  const double psi = limiter_psi(limiter, limiter_ratio(phi_u, phi_c, phi_d));
  return phi_c + 0.5 * psi * (phi_d - phi_c);
}

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
