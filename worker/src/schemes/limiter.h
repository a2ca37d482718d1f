// SPDX-License-Identifier: GPL-3.0-or-later
// TVD flux limiters ψ(r) (PHYSICS.md §5), as pure functions.
//
// r = (φ_C − φ_U)/(φ_D − φ_C), C the upwind cell; the face value is
// φ_f = φ_C + ½ ψ(r) (φ_D − φ_C). fou: ψ = 0; central: ψ = 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

enum class Limiter { kFou, kCentral, kMinmod, kVanLeer, kMuscl, kSuperbee };

// ψ(r). Inline, like the two below: evaluated at every face of every
// momentum assembly.
inline double limiter_psi(Limiter limiter, double r) {
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
// r from the upwind-upwind (U), upwind (C) and downwind (D) values.
inline double limiter_ratio(double phi_u, double phi_c, double phi_d) {
  constexpr double kLargeRatio = 1e30;
  const double num = phi_c - phi_u;
  const double den = phi_d - phi_c;
  if (den == 0.0) {
    if (num == 0.0) return 0.0;
    return num > 0 ? kLargeRatio : -kLargeRatio;
  }
  return std::clamp(num / den, -kLargeRatio, kLargeRatio);
}

// Face value φ_f = φ_C + ½ ψ(r) (φ_D − φ_C).
inline double limited_face_value(Limiter limiter, double phi_u, double phi_c, double phi_d) {
  const double psi = limiter_psi(limiter, limiter_ratio(phi_u, phi_c, phi_d));
  return phi_c + 0.5 * psi * (phi_d - phi_c);
}

struct LimiterInfo {
  Limiter limiter;
  std::string_view name;       // JSON name, e.g. "superbee"
  std::string_view reference;
  int formal_order;            // 1 for fou, 2 otherwise (away from extrema)
};

const std::vector<LimiterInfo>& limiters();
std::optional<Limiter> limiter_from_name(std::string_view name);
std::string_view limiter_name(Limiter limiter);
std::string limiter_names();

}  // namespace gridfree
