// SPDX-License-Identifier: GPL-3.0-or-later
// Typed parameters of each generator kind, read from the generator object
// (schemas/job.schema.json, definitions/generator), and the kind-specific
// generators behind generate_particles (particles/generators.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/case_spec.h"
#include "core/input_error.h"
#include "particles/generators.h"

namespace gridfree {

// Largest fraction asked of random sequential addition: its saturation
// (jamming) density for equal spheres is ≈ 0.38, approached ever more slowly.
inline constexpr double kMaxRsaFraction = 0.37;
// Largest emulsion fraction of sscp_like (random close packing ≈ 0.64).
inline constexpr double kMaxLatticeFraction = 0.64;

struct BurstingBubbleParams {
  std::uint64_t seed = 0;
};

struct UniformRandomParams {
  double solids_fraction = 0;
  std::uint64_t seed = 0;
  std::array<double, 3> min_dp{};  // region, particle diameters
  std::array<double, 3> max_dp{};  // (default: the whole domain)
};

// How sscp_like builds its emulsion: a random dense packing by overlap
// removal (default), the same by compression of growing spheres, or the
// jittered FCC lattice (kept to show how cells alias a crystal).
enum class SscpEmulsion { kRandom, kCompression, kLattice };

// Largest emulsion fraction of the random packing: overlap removal from
// random centres slows sharply towards random close packing (≈ 0.64):
// between walls, 230 sweeps at 0.55, 730 at 0.589, 3 400 at 0.60, and 0.62
// unfinished after 8 minutes (docs/PARTICLES.md).
inline constexpr double kMaxRandomEmulsionFraction = 0.60;
// Largest emulsion fraction of the compression: 0.60 reached in 3.9 s CPU
// (overlap removal: 16 s), 0.62 unfinished after 26 minutes
// (docs/PARTICLES.md).
inline constexpr double kMaxCompressionFraction = 0.60;

struct SscpLikeParams {
  std::uint64_t seed = 0;
  double bed_height_dp = 0;
  double solids_fraction = 0;         // emulsion ε_s
  int bubbles = 0;
  double bubble_radius_dp = 0;
  double bubble_solids_fraction = 0.01;
  SscpEmulsion emulsion = SscpEmulsion::kRandom;
  int relaxation_sweeps = 20;         // hard-sphere Monte Carlo sweeps (lattice only)
};

// Readers: add problems (type errors and the kind's checks against the case).
BurstingBubbleParams read_bursting_bubble(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems);
UniformRandomParams read_uniform_random(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems);
SscpLikeParams read_sscp_like(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems);

// Generators (parameters already checked). `where` names the generator
// object in errors raised while placing.
GeneratedParticles generate_bursting_bubble(const BurstingBubbleParams& p, const CaseSpec& c, const std::string& where);
GeneratedParticles generate_uniform_random(const UniformRandomParams& p, const CaseSpec& c, const std::string& where);
GeneratedParticles generate_sscp_like(const SscpLikeParams& p, const CaseSpec& c, const std::string& where);

// Shared helpers.
double particle_volume(double d);                       // π d³ / 6
std::array<bool, 3> periodic_axes(const CaseSpec& c);
RegionReport make_report(std::string name, double volume, double target, std::size_t count, double d);

}  // namespace gridfree
