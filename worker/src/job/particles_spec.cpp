// SPDX-License-Identifier: GPL-3.0-or-later
#include "job/particles_spec.h"

#include "core/json_fields.h"
#include "core/schema_validation.h"
#include "job/case_parts.h"
#include "job/case_plausibility.h"
#include "particles/generators.h"

namespace gridfree {

CaseSpec parse_particles_spec(const nlohmann::json& doc, const std::filesystem::path& base_dir) {
  const std::vector<Problem> schema_problems = validate_against_schema(doc, "particles.schema");
  if (!schema_problems.empty()) throw InputError(schema_problems);

  ProblemList problems;
  CaseSpec c;
  c.name = "particles";
  c.domain_dp = read_vector3(doc, "domain_dp", "", problems);
  check_domain(c.domain_dp, "/domain_dp", problems);
  c.particle_diameter_cm = read_number(doc, "particle_diameter_cm", "", problems);
  if (!(c.particle_diameter_cm > 0)) problems.add("/particle_diameter_cm", "must be > 0");
  check_geometry_plausibility(c.domain_dp, c.particle_diameter_cm, "", problems);
  c.particles = parse_particle_source(doc, "", base_dir, problems);

  if (doc.contains("boundaries")) {
    c.boundaries = parse_boundaries(doc.at("boundaries"), "/boundaries", problems);
  } else {
    const auto* g = std::get_if<GeneratorSpec>(&c.particles);
    const bool walls = g != nullptr && g->kind == "sscp_like";
    const BoundarySpec side{walls ? BoundaryKind::kWall : BoundaryKind::kPeriodic, 0, 0};
    c.boundaries[0] = {side, side};
    c.boundaries[2] = {side, side};
    c.boundaries[1][0] = {BoundaryKind::kMassInflow, 0, 0};
    c.boundaries[1][1] = {BoundaryKind::kPressureOutflow, 0, 0};
  }
  c.particle_velocity = parse_particle_velocity(read_object(doc, "particle_velocity", "", problems),
                                                "/particle_velocity", problems);
  // Probes are irrelevant here: keep them inside whatever domain was given.
  c.probes = {0.25 * c.domain_dp[1], 0.75 * c.domain_dp[1]};

  if (const auto* g = std::get_if<GeneratorSpec>(&c.particles); g != nullptr && problems.empty())
    check_generator(*g, c, problems);
  problems.throw_if_any();
  return c;
}

}  // namespace gridfree
