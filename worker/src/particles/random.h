// SPDX-License-Identifier: GPL-3.0-or-later
// Portable random numbers for particle generation.
//
// std::uniform_real_distribution and std::normal_distribution are
// implementation-defined, so files generated from the same seed could differ
// between standard libraries. Here the engine is std::mt19937_64 (fully
// specified by the standard) and the mappings are our own:
//   uniform in [0,1):  u = (x >> 11) · 2⁻⁵³          (53 random mantissa bits)
//   normal N(0,1):     Box–Muller, z = √(−2 ln u₁) cos(2π u₂), u₁ ∈ (0,1]
// (the sine partner is kept for the next call).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace gridfree {

class ParticleRandom {
 public:
  explicit ParticleRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n), n > 0 (modulo; bias < n/2⁶⁴, negligible here).
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }
  // Standard normal deviate.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = static_cast<double>((engine_() >> 11) + 1) * 0x1.0p-53;  // (0, 1]
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace gridfree
