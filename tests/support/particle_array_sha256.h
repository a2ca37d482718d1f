// SPDX-License-Identifier: GPL-3.0-or-later
// The SHA-256 of a particle array (x, y, z, d as little-endian doubles, in
// output order): what the generated-bed pins compare.
#pragma once

#include <cstring>
#include <string>

#include "job/job_hash.h"
#include "particles/particle.h"

namespace gridfree::test_support {

inline std::string particle_array_sha256(const ParticleSet& set) {
  std::string bytes;
  bytes.reserve(set.particles.size() * 4 * sizeof(double));
  for (const Particle& p : set.particles)
    for (double v : {p.x, p.y, p.z, p.d}) {
      char b[sizeof(double)];
      std::memcpy(b, &v, sizeof(double));
      bytes.append(b, sizeof(double));
    }
  return sha256_hex(bytes);
}

}  // namespace gridfree::test_support
