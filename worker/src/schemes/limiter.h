// TVD flux limiters ψ(r) (PHYSICS.md §5), as pure functions.
//
// r = (φ_C − φ_U)/(φ_D − φ_C), C the upwind cell; the face value is
// φ_f = φ_C + ½ ψ(r) (φ_D − φ_C). fou: ψ = 0; central: ψ = 1.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

enum class Limiter { kFou, kCentral, kMinmod, kVanLeer, kMuscl, kSuperbee };

double limiter_psi(Limiter limiter, double r);

// r from the upwind-upwind (U), upwind (C) and downwind (D) values; safe when
// φ_D = φ_C (returns a large signed value, so ψ saturates, never NaN).
double limiter_ratio(double phi_u, double phi_c, double phi_d);

// Face value φ_f = φ_C + ½ ψ(r) (φ_D − φ_C).
double limited_face_value(Limiter limiter, double phi_u, double phi_c, double phi_d);

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
