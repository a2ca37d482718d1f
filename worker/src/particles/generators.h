// SPDX-License-Identifier: GPL-3.0-or-later
// Seeded particle configurations (PHYSICS.md §6, docs/PARTICLES.md).
//
//   bursting_bubble  the paper's fictitious bursting bubble: ε_s = 0.30 for
//                    y* < 28 except a sphere (radius 5, centre (15,22,5)) at
//                    0.01; ε_s = 0.01 for 28 ≤ y* < 50; empty above
//   uniform_random   a uniform random bed in a box (RSA, ε_s ≤ 0.38)
//   sscp_like        a packed emulsion (ε_s ≈ 0.55–0.6: a random dense
//                    packing, or with "emulsion": "lattice" a jittered FCC
//                    lattice) with a few random bubbles at ε_s ≈ 0.01
// Counts per region are round(ε_s,target · V_region / V_p), V_p = π d³/6.
// Same spec and seed → the same particles, bit for bit, on any platform
// with IEEE doubles (see particles/random.h).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/case_spec.h"
#include "core/input_error.h"
#include "particles/particle.h"

namespace gridfree {

// What a generator put where: one entry per region.
struct RegionReport {
  std::string name;
  double volume_cm3 = 0;
  double target_fraction = 0;   // ε_s asked for
  std::size_t count = 0;        // particles whose centre lies in the region
  double solids_fraction = 0;   // count · V_p / volume
};

struct GeneratedParticles {
  ParticleSet set;
  std::vector<RegionReport> regions;
};

// Checks the generator's parameters against the case (fractions reachable,
// regions inside the domain, bubbles fit, ...); problems are named
// "<spec.where>/<field>". Does not generate.
void check_generator(const GeneratorSpec& spec, const CaseSpec& case_spec, ProblemList& problems);

// Generates the configuration; throws InputError for bad parameters or when
// the placement cannot reach the requested count.
GeneratedParticles generate_particles_with_report(const GeneratorSpec& spec, const CaseSpec& case_spec);
ParticleSet generate_particles(const GeneratorSpec& spec, const CaseSpec& case_spec);

// What turns a generator spec into particles: generate_particles_with_report,
// or the same behind a cache (job/bed_cache.h). Empty = generate.
using BedGenerator = std::function<GeneratedParticles(const GeneratorSpec&, const CaseSpec&)>;

// "Thermal" particle velocities (the PC3t variant): every component of every
// particle drawn from N(0, thermal_cm_s²) with its own seeded stream
// (Box–Muller, particles/random.h). No-op when thermal_cm_s is 0.
void apply_thermal_velocity(ParticleSet& set, const ParticleVelocitySpec& spec);

// The generator kinds, for messages: "bursting_bubble, uniform_random, sscp_like".
std::string generator_kind_names();

}  // namespace gridfree
