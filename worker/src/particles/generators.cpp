// SPDX-License-Identifier: GPL-3.0-or-later
// Dispatch by generator kind, the parameter readers and their checks
// against the case (particles/generator_params.h).
#include "particles/generators.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/json_fields.h"
#include "particles/generator_params.h"

namespace gridfree {
namespace {

std::string dims(const std::array<double, 3>& v) {
  std::ostringstream os;
  os << v[0] << " x " << v[1] << " x " << v[2];
  return os.str();
}

void check_fraction(double value, double max, const std::string& where, const std::string& why, ProblemList& problems) {
  if (!(value > 0)) problems.add(where, "must be > 0");
  else if (value > max) {
    std::ostringstream os;
    os << value << " is above " << max << ", the most " << why << " reaches";
    problems.add(where, os.str());
  }
}

}  // namespace

double particle_volume(double d) { return std::numbers::pi * d * d * d / 6.0; }

std::array<bool, 3> periodic_axes(const CaseSpec& c) { return {c.periodic(0), c.periodic(1), c.periodic(2)}; }

RegionReport make_report(std::string name, double volume, double target, std::size_t count, double d) {
  RegionReport r;
  r.name = std::move(name);
  r.volume_cm3 = volume;
  r.target_fraction = target;
  r.count = count;
  r.solids_fraction = volume > 0 ? static_cast<double>(count) * particle_volume(d) / volume : 0.0;
  return r;
}

std::string generator_kind_names() { return "bursting_bubble, uniform_random, sscp_like"; }

BurstingBubbleParams read_bursting_bubble(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems) {
  BurstingBubbleParams p;
  p.seed = read_seed(spec.params, "seed", spec.where, problems);
  // The bubble sphere (centre (15,22,5), radius 5) must lie inside the dense
  // bed y* < 28 and inside the domain.
  const std::array<double, 3> needed{20, 28, 10};
  for (int a = 0; a < 3; ++a) {
    if (c.domain_dp[a] < needed[a]) {
      problems.add(child_pointer(spec.where, "kind"),
                   "bursting_bubble needs a domain of at least " + dims(needed) +
                       " particle diameters (the bubble must fit in the dense bed), got " + dims(c.domain_dp));
      break;
    }
  }
  return p;
}

UniformRandomParams read_uniform_random(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems) {
  UniformRandomParams p;
  p.solids_fraction = read_number(spec.params, "solids_fraction", spec.where, problems);
  p.seed = read_seed(spec.params, "seed", spec.where, problems);
  check_fraction(p.solids_fraction, kMaxRsaFraction, child_pointer(spec.where, "solids_fraction"),
                 "random sequential addition", problems);
  p.min_dp = {0, 0, 0};
  p.max_dp = c.domain_dp;
  if (spec.params.is_object() && spec.params.contains("region_dp")) {
    const std::string rw = child_pointer(spec.where, "region_dp");
    const auto& region = read_object(spec.params, "region_dp", spec.where, problems, true);
    p.min_dp = read_vector3(region, "min", rw, problems);
    p.max_dp = read_vector3(region, "max", rw, problems);
    bool inside = true, wide = true;
    for (int a = 0; a < 3; ++a) {
      inside = inside && p.min_dp[a] >= 0 && p.max_dp[a] <= c.domain_dp[a];
      wide = wide && p.max_dp[a] - p.min_dp[a] >= 1;
    }
    if (!inside) problems.add(rw, "the region must lie inside the domain " + dims(c.domain_dp));
    else if (!wide) problems.add(rw, "the region must be at least one particle diameter wide on every axis");
  }
  return p;
}

SscpLikeParams read_sscp_like(const GeneratorSpec& spec, const CaseSpec& c, ProblemList& problems) {
  SscpLikeParams p;
  const auto& j = spec.params;
  const std::string& w = spec.where;
  p.seed = read_seed(j, "seed", w, problems);
  p.bed_height_dp = read_number(j, "bed_height_dp", w, problems);
  p.solids_fraction = read_number(j, "solids_fraction", w, problems);
  p.bubbles = static_cast<int>(read_integer(j, "bubbles", w, problems));
  p.bubble_radius_dp = read_number(j, "bubble_radius_dp", w, problems);
  p.bubble_solids_fraction = read_number(j, "bubble_solids_fraction", w, problems, 0.01);
  const std::string emulsion = read_string(j, "emulsion", w, problems, "random");
  if (emulsion == "lattice") p.emulsion = SscpEmulsion::kLattice;
  else if (emulsion == "compression") p.emulsion = SscpEmulsion::kCompression;
  else if (emulsion != "random")
    problems.add(child_pointer(w, "emulsion"), "'" + emulsion + "' is not one of random, compression, lattice");
  p.relaxation_sweeps = static_cast<int>(read_integer(j, "relaxation_sweeps", w, problems, 20));
  if (p.emulsion != SscpEmulsion::kLattice && j.is_object() && j.contains("relaxation_sweeps"))
    problems.add(child_pointer(w, "relaxation_sweeps"), "applies only to \"emulsion\": \"lattice\"");

  if (p.emulsion == SscpEmulsion::kLattice)
    check_fraction(p.solids_fraction, kMaxLatticeFraction, child_pointer(w, "solids_fraction"),
                   "the jittered lattice", problems);
  else if (p.emulsion == SscpEmulsion::kCompression)
    check_fraction(p.solids_fraction, kMaxCompressionFraction, child_pointer(w, "solids_fraction"),
                   "the compression", problems);
  else
    check_fraction(p.solids_fraction, kMaxRandomEmulsionFraction, child_pointer(w, "solids_fraction"),
                   "the random dense packing", problems);
  if (p.bed_height_dp < 2 || p.bed_height_dp > c.domain_dp[1])
    problems.add(child_pointer(w, "bed_height_dp"), "must be between 2 and the domain height " +
                                                        std::to_string(c.domain_dp[1]) + " (particle diameters)");
  for (int a = 0; a < 3; a += 2) {
    if (c.domain_dp[a] < 2) problems.add(child_pointer(w, "kind"), "sscp_like needs a domain at least 2 diameters wide");
  }
  if (p.bubbles < 0) problems.add(child_pointer(w, "bubbles"), "must be >= 0");
  if (p.bubble_radius_dp <= 0) problems.add(child_pointer(w, "bubble_radius_dp"), "must be > 0");
  if (p.bubble_solids_fraction < 0 || p.bubble_solids_fraction >= 0.3)
    problems.add(child_pointer(w, "bubble_solids_fraction"), "must be in [0, 0.3)");
  if (p.relaxation_sweeps < 0) problems.add(child_pointer(w, "relaxation_sweeps"), "must be >= 0");
  if (p.bubbles > 0 && p.bubble_radius_dp > 0 && p.bed_height_dp > 0) {
    const double diameter = 2 * p.bubble_radius_dp;
    bool fits = diameter <= p.bed_height_dp;
    for (int a = 0; a < 3; a += 2)
      fits = fits && (c.periodic(a) ? diameter < c.domain_dp[a] : diameter <= c.domain_dp[a]);
    if (!fits) problems.add(child_pointer(w, "bubble_radius_dp"), "a bubble this size does not fit in the bed");
    const double bubble_volume = p.bubbles * 4.0 / 3.0 * std::numbers::pi * std::pow(p.bubble_radius_dp, 3);
    const double bed_volume = c.domain_dp[0] * p.bed_height_dp * c.domain_dp[2];
    if (bubble_volume > 0.5 * bed_volume)
      problems.add(child_pointer(w, "bubbles"), "the bubbles would fill more than half of the bed");
  }
  return p;
}

void check_generator(const GeneratorSpec& spec, const CaseSpec& case_spec, ProblemList& problems) {
  if (spec.kind == "bursting_bubble") read_bursting_bubble(spec, case_spec, problems);
  else if (spec.kind == "uniform_random") read_uniform_random(spec, case_spec, problems);
  else if (spec.kind == "sscp_like") read_sscp_like(spec, case_spec, problems);
  else
    problems.add(child_pointer(spec.where, "kind"),
                 std::string("'") + spec.kind + "' is not one of " + generator_kind_names());
}

GeneratedParticles generate_particles_with_report(const GeneratorSpec& spec, const CaseSpec& case_spec) {
  ProblemList problems;
  if (!(case_spec.particle_diameter_cm > 0))
    problems.add("particle_diameter_cm", "must be > 0 to generate particles");
  GeneratedParticles out;
  if (spec.kind == "bursting_bubble") {
    const auto p = read_bursting_bubble(spec, case_spec, problems);
    problems.throw_if_any();
    out = generate_bursting_bubble(p, case_spec, spec.where);
  } else if (spec.kind == "uniform_random") {
    const auto p = read_uniform_random(spec, case_spec, problems);
    problems.throw_if_any();
    out = generate_uniform_random(p, case_spec, spec.where);
  } else if (spec.kind == "sscp_like") {
    const auto p = read_sscp_like(spec, case_spec, problems);
    problems.throw_if_any();
    out = generate_sscp_like(p, case_spec, spec.where);
  } else {
    check_generator(spec, case_spec, problems);
    problems.throw_if_any();
  }
  return out;
}

ParticleSet generate_particles(const GeneratorSpec& spec, const CaseSpec& case_spec) {
  return generate_particles_with_report(spec, case_spec).set;
}

}  // namespace gridfree
