// SPDX-License-Identifier: GPL-3.0-or-later
// TVD limiters (PHYSICS.md §5): the defining properties, checked on a dense
// set of r (exact arithmetic on the formulas, so tolerances are round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "schemes/limiter.h"

namespace gridfree {
namespace {

const std::vector<Limiter> kTvd = {Limiter::kMinmod, Limiter::kVanLeer, Limiter::kMuscl, Limiter::kSuperbee};

// r from −50 to 50, denser near 0 and 1, plus the special points.
std::vector<double> sample_r() {
  std::vector<double> r = {0.0, 0.5, 1.0, 2.0, 3.0, 1e-12, -1e-12, 1e6, -1e6};
  for (int i = -2000; i <= 2000; ++i) r.push_back(i * 0.025);
  for (int i = 1; i <= 60; ++i) r.push_back(std::pow(10.0, -6.0 + 0.2 * i));
  return r;
}

TEST(Limiter, ValuesAtOneAndSpecialPoints) {
  for (Limiter l : kTvd) EXPECT_DOUBLE_EQ(limiter_psi(l, 1.0), 1.0) << limiter_name(l);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kCentral, 1.0), 1.0);
  EXPECT_EQ(limiter_psi(Limiter::kFou, 1.0), 0.0);
  // Hand values: minmod(0.5) = 0.5; van Leer(3) = 6/4; MUSCL(0.5) = 0.75 and
  // MUSCL(0.2) = 0.4; superbee(0.25) = 0.5, superbee(1.5) = 1.5, superbee(5) = 2.
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kMinmod, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kVanLeer, 3.0), 1.5);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kMuscl, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kMuscl, 0.2), 0.4);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kSuperbee, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kSuperbee, 1.5), 1.5);
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kSuperbee, 5.0), 2.0);
}

TEST(Limiter, ZeroForNonPositiveRatio) {
  for (double r : sample_r()) {
    if (r > 0) continue;
    for (Limiter l : kTvd) EXPECT_EQ(limiter_psi(l, r), 0.0) << limiter_name(l) << " r=" << r;
    EXPECT_EQ(limiter_psi(Limiter::kFou, r), 0.0);
    EXPECT_EQ(limiter_psi(Limiter::kCentral, r), 1.0);  // central is not TVD
  }
}

TEST(Limiter, InsideTvdRegion) {
  // Sweby's region: 0 ≤ ψ(r) ≤ min(2r, 2) for r > 0.
  for (double r : sample_r()) {
    if (r <= 0) continue;
    for (Limiter l : kTvd) {
      const double psi = limiter_psi(l, r);
      EXPECT_GE(psi, 0.0) << limiter_name(l) << " r=" << r;
      EXPECT_LE(psi, std::min(2.0 * r, 2.0) * (1 + 1e-15)) << limiter_name(l) << " r=" << r;
    }
  }
}

TEST(Limiter, Symmetry) {
  // ψ(r)/r = ψ(1/r) holds for minmod, van Leer, MUSCL (monotonized central)
  // and superbee; for central (ψ = 1) it does not.
  for (double r : sample_r()) {
    if (r <= 0 || r > 1e5 || r < 1e-5) continue;
    for (Limiter l : kTvd)
      EXPECT_NEAR(limiter_psi(l, r) / r, limiter_psi(l, 1.0 / r), 1e-14 * (1 + 1.0 / r))
          << limiter_name(l) << " r=" << r;
  }
  EXPECT_NE(limiter_psi(Limiter::kCentral, 4.0) / 4.0, limiter_psi(Limiter::kCentral, 0.25));
}

TEST(Limiter, RatioIsSafeOnFlatDownwind) {
  // φ_D = φ_C: r is ±1e30 with the sign of φ_C − φ_U (0 if that is 0 too),
  // ψ is finite, and the face value is φ_C exactly.
  EXPECT_EQ(limiter_ratio(1.0, 2.0, 2.0), 1e30);
  EXPECT_EQ(limiter_ratio(3.0, 2.0, 2.0), -1e30);
  EXPECT_EQ(limiter_ratio(2.0, 2.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(limiter_ratio(0.0, 1.0, 3.0), 0.5);
  // A quotient that would overflow to inf (1e300/1e-10) is clamped.
  EXPECT_EQ(limiter_ratio(-1e300, 0.0, 1e-10), 1e30);
  EXPECT_EQ(limiter_ratio(1e300, 0.0, 1e-10), -1e30);
  for (const auto& info : limiters()) {
    for (double r : {1e30, -1e30, std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()})
      EXPECT_TRUE(std::isfinite(limiter_psi(info.limiter, r))) << info.name << " r=" << r;
    EXPECT_EQ(limited_face_value(info.limiter, 1.0, 2.0, 2.0), 2.0);
    EXPECT_EQ(limited_face_value(info.limiter, 2.0, 2.0, 2.0), 2.0);
  }
  EXPECT_DOUBLE_EQ(limiter_psi(Limiter::kVanLeer, 1e30), 2.0);
}

TEST(Limiter, FaceValueBoundedByNeighbours) {
  // For TVD limiters 0 ≤ ψ ≤ 2 keeps φ_f = φ_C + ½ψ(φ_D − φ_C) between φ_C
  // and φ_D; checked on all triples of 23 scattered values.
  std::vector<double> values;
  for (int i = 0; i < 23; ++i) values.push_back(std::sin(1.7 * i) * (1 + i % 5));
  for (Limiter l : kTvd)
    for (double u : values)
      for (double c : values)
        for (double d : values) {
          const double f = limited_face_value(l, u, c, d);
          const double lo = std::min(c, d), hi = std::max(c, d);
          const double slack = 1e-14 * (1 + std::abs(c) + std::abs(d));
          EXPECT_GE(f, lo - slack) << limiter_name(l);
          EXPECT_LE(f, hi + slack) << limiter_name(l);
        }
  // Hand value: superbee on a smooth ramp (r = 1) is central: φ_f = (φ_C + φ_D)/2.
  EXPECT_DOUBLE_EQ(limited_face_value(Limiter::kSuperbee, 1.0, 2.0, 3.0), 2.5);
  EXPECT_DOUBLE_EQ(limited_face_value(Limiter::kFou, 1.0, 2.0, 3.0), 2.0);
  // At an extremum (r < 0) every TVD limiter falls back to upwind.
  for (Limiter l : kTvd) EXPECT_EQ(limited_face_value(l, 3.0, 2.0, 3.0), 2.0);
}

TEST(Limiter, RegistryRoundTrips) {
  EXPECT_EQ(limiters().size(), 6u);
  for (const auto& info : limiters()) {
    EXPECT_EQ(limiter_from_name(info.name), info.limiter);
    EXPECT_EQ(limiter_name(info.limiter), info.name);
    EXPECT_EQ(info.formal_order, info.limiter == Limiter::kFou ? 1 : 2);
    EXPECT_FALSE(info.reference.empty());
  }
  EXPECT_FALSE(limiter_from_name("quick").has_value());
  EXPECT_EQ(limiter_names(), "fou, central, minmod, van_leer, muscl, superbee");
}

}  // namespace
}  // namespace gridfree
