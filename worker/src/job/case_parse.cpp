// SPDX-License-Identifier: GPL-3.0-or-later
// parse_case and its pieces (job/job_spec.h, job/case_parts.h): a case
// object → CaseSpec, with the semantic checks the schema cannot express:
// positive sizes, probes 0 < y1 < y2 < L_y*, particle files that exist,
// generator parameters that fit the domain, physical plausibility
// (job/case_plausibility.h).
#include <cmath>

#include "core/json_fields.h"
#include "core/text.h"
#include "job/case_parts.h"
#include "job/case_plausibility.h"
#include "job/job_spec.h"
#include "particles/generators.h"

namespace gridfree {
namespace {

BoundarySpec parse_y_boundary(const nlohmann::json& obj, const std::string& key, const std::string& where,
                              ProblemList& problems) {
  BoundarySpec b;
  const std::string at = child_pointer(where, key);
  if (!obj.contains(key)) {
    problems.add(at, "required, but missing");
    return b;
  }
  const nlohmann::json& v = obj.at(key);
  if (v.is_string()) {
    if (v != "wall") problems.add(at, "must be \"wall\" or an object with a type");
    return b;
  }
  const std::string type = read_string(v, "type", at, problems);
  if (type == "wall") {
    b.kind = BoundaryKind::kWall;
  } else if (type == "mass_inflow") {
    b.kind = BoundaryKind::kMassInflow;
    b.superficial_velocity_cm_s = read_number(v, "superficial_velocity_cm_s", at, problems);
    if (b.superficial_velocity_cm_s < 0)
      problems.add(child_pointer(at, "superficial_velocity_cm_s"), "the inflow velocity must be >= 0");
    if (key != "y_low") problems.add(child_pointer(at, "type"), "mass_inflow is supported at y_low only");
  } else if (type == "pressure_outflow") {
    b.kind = BoundaryKind::kPressureOutflow;
    b.pressure_dyn_cm2 = read_number(v, "pressure_dyn_cm2", at, problems, 0.0);
    if (key != "y_high") problems.add(child_pointer(at, "type"), "pressure_outflow is supported at y_high only");
  } else if (!type.empty()) {
    problems.add(child_pointer(at, "type"), "'" + type + "' is not one of mass_inflow, pressure_outflow, wall");
  }
  return b;
}

}  // namespace

void check_domain(const std::array<double, 3>& domain_dp, const std::string& where, ProblemList& problems) {
  for (std::size_t a = 0; a < 3; ++a)
    if (!(domain_dp[a] > 0)) problems.add(child_pointer(where, a), "the domain size must be > 0");
}

CaseBoundaries parse_boundaries(const nlohmann::json& obj, const std::string& where, ProblemList& problems) {
  CaseBoundaries b{};
  for (int axis : {0, 2}) {
    const std::string key = axis == 0 ? "x" : "z";
    const std::string kind = read_string(obj, key, where, problems);
    BoundarySpec side;
    if (kind == "periodic") side.kind = BoundaryKind::kPeriodic;
    else if (kind == "wall") side.kind = BoundaryKind::kWall;
    else if (!kind.empty()) problems.add(child_pointer(where, key), "'" + kind + "' is not one of periodic, wall");
    b[axis] = {side, side};  // periodic on both sides, or neither
  }
  b[1][0] = parse_y_boundary(obj, "y_low", where, problems);
  b[1][1] = parse_y_boundary(obj, "y_high", where, problems);
  return b;
}

// `units` (required) and `timestep` (optional) belong to LAMMPS dumps only:
// CSV and MFiX files are in cm and hold one configuration.
void parse_lammps_options(const nlohmann::json& obj, FileSpec& f, const std::string& where, ProblemList& problems) {
  const bool lammps = f.format == "lammps";
  for (const char* key : {"units", "timestep"})
    if (obj.contains(key) && !lammps && !f.format.empty())
      problems.add(child_pointer(where, key), "applies to format lammps only (" + f.format + " files are in cm and hold one configuration)");
  if (!lammps) return;
  if (!obj.contains("units")) {
    problems.add(where.empty() ? "/" : where, "a lammps dump needs \"units\": \"si\" (lengths in m) or \"cgs\" (cm)");
  } else {
    f.units = read_string(obj, "units", where, problems);
    if (!f.units.empty() && f.units != "si" && f.units != "cgs")
      problems.add(child_pointer(where, "units"), "'" + f.units + "' is not one of si, cgs");
  }
  if (obj.contains("timestep")) {
    const nlohmann::json& t = obj.at("timestep");
    if (t.is_number_integer() && t.get<std::int64_t>() >= 0) f.timestep = t.get<std::int64_t>();
    else problems.add(child_pointer(where, "timestep"), "must be a whole number >= 0");
  }
}

ParticleSource parse_particle_source(const nlohmann::json& obj, const std::string& where,
                                     const std::filesystem::path& base_dir, ProblemList& problems) {
  const int given = obj.contains("generator") + obj.contains("file") + obj.contains("uniform");
  if (given != 1) {
    problems.add(where.empty() ? "/" : where, "give exactly one of generator, file (with format) or uniform");
    return UniformSpec{};
  }
  if (obj.contains("generator")) {
    GeneratorSpec g;
    g.where = child_pointer(where, "generator");
    g.params = obj.at("generator");
    g.kind = read_string(g.params, "kind", g.where, problems);
    return g;
  }
  if (obj.contains("file")) {
    FileSpec f;
    const std::string name = read_string(obj, "file", where, problems);
    f.format = read_string(obj, "format", where, problems);
    if (!f.format.empty() && f.format != "csv" && f.format != "mfix" && f.format != "lammps")
      problems.add(child_pointer(where, "format"), "'" + f.format + "' is not one of csv, mfix, lammps");
    parse_lammps_options(obj, f, where, problems);
    if (!name.empty()) {
      f.path = std::filesystem::path(name);
      if (f.path.is_relative()) f.path = base_dir / f.path;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(f.path, ec))
        problems.add(child_pointer(where, "file"), "no such file: " + f.path.string());
    }
    return f;
  }
  UniformSpec u;
  const std::string at = child_pointer(where, "uniform");
  u.solids_fraction = read_number(read_object(obj, "uniform", where, problems, true), "solids_fraction", at, problems);
  if (!(u.solids_fraction > 0 && u.solids_fraction < 1))  // φ = 0: no particles, no drag, nothing to verify
    problems.add(child_pointer(at, "solids_fraction"),
                 "must be in (0, 1): a bed without particles has no drag, and its dp* would be only the gas's "
                 "wall friction (docs/INTERFACE.md)");
  return u;
}

ParticleVelocitySpec parse_particle_velocity(const nlohmann::json& obj, const std::string& where,
                                             ProblemList& problems) {
  ParticleVelocitySpec v;
  v.thermal_cm_s = read_number(obj, "thermal_cm_s", where, problems, 0.0);
  v.seed = read_seed(obj, "seed", where, problems, 0);
  if (v.thermal_cm_s < 0) problems.add(child_pointer(where, "thermal_cm_s"), "must be >= 0");
  return v;
}

CaseSpec parse_case(const nlohmann::json& j, const std::string& path, const std::filesystem::path& base_dir,
                    ProblemList& problems) {
  CaseSpec c;
  if (!j.is_object()) {
    problems.add(path, "a case must be an object");
    return c;
  }
  c.name = read_string(j, "name", path, problems, "");
  c.domain_dp = read_vector3(j, "domain_dp", path, problems);
  check_domain(c.domain_dp, child_pointer(path, "domain_dp"), problems);
  c.particle_diameter_cm = read_number(j, "particle_diameter_cm", path, problems);
  if (!(c.particle_diameter_cm > 0)) problems.add(child_pointer(path, "particle_diameter_cm"), "must be > 0");

  const std::string gas_at = child_pointer(path, "gas");
  const auto& gas = read_object(j, "gas", path, problems, true);
  c.gas.density_g_cm3 = read_number(gas, "density_g_cm3", gas_at, problems);
  c.gas.viscosity_g_cm_s = read_number(gas, "viscosity_g_cm_s", gas_at, problems);
  if (!(c.gas.density_g_cm3 > 0)) problems.add(child_pointer(gas_at, "density_g_cm3"), "the gas density must be > 0");
  if (!(c.gas.viscosity_g_cm_s > 0))
    problems.add(child_pointer(gas_at, "viscosity_g_cm_s"), "the gas viscosity must be > 0");

  c.gravity_cm_s2 = read_vector3(j, "gravity_cm_s2", path, problems, std::array<double, 3>{0, 0, 0});
  c.boundaries = parse_boundaries(read_object(j, "boundaries", path, problems, true), child_pointer(path, "boundaries"),
                                  problems);
  c.particles = parse_particle_source(read_object(j, "particles", path, problems, true),
                                      child_pointer(path, "particles"), base_dir, problems);
  c.particle_velocity = parse_particle_velocity(read_object(j, "particle_velocity", path, problems),
                                                child_pointer(path, "particle_velocity"), problems);

  const std::string probe_at = child_pointer(child_pointer(path, "probes"), "pressure_drop");
  const auto& probes = read_object(read_object(j, "probes", path, problems), "pressure_drop",
                                   child_pointer(path, "probes"), problems);
  c.probes.y1_dp = read_number(probes, "y1_dp", probe_at, problems, 4.0);
  c.probes.y2_dp = read_number(probes, "y2_dp", probe_at, problems, 104.0);
  if (!(c.probes.y1_dp > 0))
    problems.add(child_pointer(probe_at, "y1_dp"), "must be > 0 (inside the domain), got " + number_text(c.probes.y1_dp));
  if (!(c.probes.y2_dp > c.probes.y1_dp))
    problems.add(child_pointer(probe_at, "y2_dp"), "must be above y1_dp = " + number_text(c.probes.y1_dp));
  if (c.domain_dp[1] > 0 && !(c.probes.y2_dp < c.domain_dp[1]))
    problems.add(child_pointer(probe_at, "y2_dp"), "must lie inside the domain (below L_y* = " +
                                                       number_text(c.domain_dp[1]) + "), got " +
                                                       number_text(c.probes.y2_dp));

  check_case_plausibility(c, path, problems);

  // Generator parameters against the domain, once the domain is sound.
  if (const auto* g = std::get_if<GeneratorSpec>(&c.particles); g != nullptr && !g->kind.empty()) {
    bool domain_ok = c.particle_diameter_cm >= kParticleDiameterRange.low &&
                     c.particle_diameter_cm <= kParticleDiameterRange.high;
    for (double l : c.domain_dp) domain_ok = domain_ok && l >= kDomainRange.low && l <= kDomainRange.high;
    if (domain_ok) check_generator(*g, c, problems);
  }
  return c;
}

}  // namespace gridfree
