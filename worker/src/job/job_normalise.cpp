// SPDX-License-Identifier: GPL-3.0-or-later
// Defaults filled into a job document (job/job_normalise.h). The values are
// the parsers' own defaults (the spec structs' initialisers), so the
// normalised document and what the solver computes cannot drift apart;
// JobNormalise.DefaultsAreTheSchemasDefaults checks them against the schema.
#include "job/job_normalise.h"

#include "job/job_spec.h"
#include "particles/generator_params.h"

namespace gridfree {
namespace {

// `obj[key]` = `value` when `obj` is an object without `key`.
void fill(nlohmann::json& obj, const char* key, const nlohmann::json& value) {
  if (obj.is_object() && !obj.contains(key)) obj[key] = value;
}

// `obj[key]`, made an empty object when `obj` is an object without it;
// nullptr when there is no object to fill.
nlohmann::json* object_at(nlohmann::json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  fill(obj, key, nlohmann::json::object());
  nlohmann::json& child = obj[key];
  return child.is_object() ? &child : nullptr;
}

void normalise_boundaries(nlohmann::json& boundaries) {
  if (!boundaries.is_object()) return;
  for (const char* side : {"y_low", "y_high"}) {
    if (!boundaries.contains(side)) continue;
    nlohmann::json& b = boundaries[side];
    if (b == "wall") b = {{"type", "wall"}};  // "wall" is short for {"type": "wall"}
    if (b.is_object() && b.value("type", "") == "pressure_outflow")
      fill(b, "pressure_dyn_cm2", BoundarySpec{}.pressure_dyn_cm2);
  }
}

void normalise_case(nlohmann::json& c) {
  if (!c.is_object()) return;
  const CaseSpec defaults;
  fill(c, "name", defaults.name);
  fill(c, "gravity_cm_s2", defaults.gravity_cm_s2);
  if (auto* v = object_at(c, "particle_velocity")) {
    fill(*v, "thermal_cm_s", defaults.particle_velocity.thermal_cm_s);
    fill(*v, "seed", defaults.particle_velocity.seed);
  }
  if (auto* probes = object_at(c, "probes"))
    if (auto* drop = object_at(*probes, "pressure_drop")) {
      fill(*drop, "y1_dp", defaults.probes.y1_dp);
      fill(*drop, "y2_dp", defaults.probes.y2_dp);
    }
  if (c.contains("boundaries")) normalise_boundaries(c["boundaries"]);
  if (c.contains("particles") && c["particles"].is_object() && c["particles"].contains("generator")) {
    nlohmann::json& g = c["particles"]["generator"];
    if (g.is_object() && g.value("kind", "") == "sscp_like") {
      const SscpLikeParams sscp;
      fill(g, "bubble_solids_fraction", sscp.bubble_solids_fraction);
      // The random emulsion is the default (and takes no relaxation sweeps);
      // a job written before it existed is migrated as "lattice"
      // (store/schema_job_hashes.cpp), so no lattice result is served for it.
      fill(g, "emulsion", std::string("random"));
      if (g.value("emulsion", "") == "lattice") fill(g, "relaxation_sweeps", sscp.relaxation_sweeps);
    }
  }
}

void normalise_numerics(nlohmann::json& n) {
  if (!n.is_object()) return;
  const NumericsSpec defaults;
  if (auto* t = object_at(n, "tolerances")) {
    fill(*t, "linear", defaults.tolerances.linear);
    fill(*t, "filter", defaults.tolerances.filter);
    fill(*t, "steady", defaults.tolerances.steady);
  }
  fill(n, "max_iterations", defaults.max_iterations);
  fill(n, "stall_window", defaults.stall_window);
  // Added after job hashes existed: its default is written by leaving it
  // out, so a job with "none" is the job from before the field.
  if (n.contains("stall_remedy") && n["stall_remedy"] == "none") n.erase("stall_remedy");
  if (n.contains("deposition") && n["deposition"].is_object()) {
    ProblemList problems;
    const DepositionSpec spec = parse_deposition(n["deposition"], "/numerics/deposition", problems);
    if (problems.empty()) n["deposition"] = deposition_json(spec, n["deposition"]);
  }
}

}  // namespace

nlohmann::json normalised_job(const nlohmann::json& job_doc) {
  nlohmann::json doc = job_doc;
  if (!doc.is_object()) return doc;
  if (doc.contains("case")) normalise_case(doc["case"]);
  if (doc.contains("numerics")) normalise_numerics(doc["numerics"]);
  return doc;
}

}  // namespace gridfree
