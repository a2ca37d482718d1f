// SPDX-License-Identifier: GPL-3.0-or-later
// The portable random streams behind the generators: the engine is the
// standard's mt19937_64 (its 10000th output from the default seed 5489 is
// fixed by the C++ standard at 9981545732273789042), our uniform mapping
// keeps its top 53 bits, and the normal deviates have mean 0 and variance 1.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/generators.h"
#include "particles/random.h"

namespace gridfree {
namespace {

TEST(ParticleRandom, UniformIsTheTop53BitsOfMt19937_64) {
  ParticleRandom rng(5489);
  double u = 0;
  for (int i = 0; i < 10000; ++i) u = rng.uniform();
  EXPECT_EQ(u, static_cast<double>(9981545732273789042ull >> 11) * 0x1.0p-53);
  ParticleRandom other(1);
  for (int i = 0; i < 100000; ++i) {
    const double x = other.uniform();
    ASSERT_TRUE(x >= 0 && x < 1);
  }
}

TEST(ParticleRandom, NormalMoments) {
  // n = 200000 deviates: the sample mean has standard error 1/√n = 0.0022
  // and the sample variance √(2/n) = 0.0032; 5 standard errors are allowed.
  ParticleRandom rng(7);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = rng.normal();
    sum += z;
    sum2 += z * z;
  }
  const double mean = sum / n, variance = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.0, 5 * 0.0022);
  EXPECT_NEAR(variance, 1.0, 5 * 0.0032);
}

TEST(ThermalVelocity, StandardDeviationPerComponentAndDeterminism) {
  ParticleSet set;
  set.particles.resize(30000);
  apply_thermal_velocity(set, {2.5, 11});
  EXPECT_TRUE(set.has_velocity);
  // Per component: n = 30000, σ = 2.5; the sample std has standard error
  // σ/√(2n) = 0.0102; allow 5 of them.
  double s[3] = {0, 0, 0};
  for (const Particle& p : set.particles) {
    s[0] += p.u * p.u;
    s[1] += p.v * p.v;
    s[2] += p.w * p.w;
  }
  for (double sum2 : s) EXPECT_NEAR(std::sqrt(sum2 / set.particles.size()), 2.5, 5 * 0.0102);

  ParticleSet again;
  again.particles.resize(30000);
  apply_thermal_velocity(again, {2.5, 11});
  EXPECT_EQ(again.particles[12345].v, set.particles[12345].v);

  ParticleSet frozen;
  frozen.particles.resize(3);
  apply_thermal_velocity(frozen, {0.0, 11});
  EXPECT_FALSE(frozen.has_velocity);
  EXPECT_EQ(frozen.particles[0].u, 0.0);
}

}  // namespace
}  // namespace gridfree
