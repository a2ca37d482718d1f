// SPDX-License-Identifier: GPL-3.0-or-later
// Job identity from the normalised document (job/job_normalise.h): a job
// that leaves out an optional field and the same job with the field's
// documented default (the schema's "default", which SchemaDefaults ties to
// the parser's) written in have one hash; so do "wall" and {"type": "wall"}.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contract_job.h"
#include "core/embedded_schemas.h"
#include "core/version.h"
#include "job/job_hash.h"
#include "job/job_normalise.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

json schema_default(const std::string& pointer) {
  static const json d = json::parse(embedded_schema("job.schema"))["definitions"];
  return d.at(json::json_pointer(pointer));
}

// The contract job with every optional field written with its default.
json defaults_written() {
  json j = test::contract_job();
  j["case"]["gravity_cm_s2"] = schema_default("/case/properties/gravity_cm_s2/default");
  j["case"]["particle_velocity"] = {
      {"thermal_cm_s", schema_default("/particle_velocity/properties/thermal_cm_s/default")},
      {"seed", schema_default("/particle_velocity/properties/seed/default")}};
  const std::string probe = "/probes/properties/pressure_drop/properties/";
  j["case"]["probes"]["pressure_drop"] = {{"y1_dp", schema_default(probe + "y1_dp/default")},
                                          {"y2_dp", schema_default(probe + "y2_dp/default")}};
  j["case"]["boundaries"]["y_high"]["pressure_dyn_cm2"] =
      schema_default("/y_boundary/else/allOf/1/then/properties/pressure_dyn_cm2/default");
  for (const char* t : {"linear", "filter", "steady"})
    j["numerics"]["tolerances"][t] = schema_default(std::string("/tolerances/properties/") + t + "/default");
  j["numerics"]["max_iterations"] = schema_default("/max_iterations/default");
  j["numerics"]["stall_window"] = schema_default("/stall_window/default");
  for (const char* f : {"diffusivity", "pre_deposition", "sampling", "integration"})
    j["numerics"]["deposition"][f] = schema_default(std::string("/deposition/properties/") + f + "/default");
  return j;
}

json without(json j, const std::string& pointer) {
  const json::json_pointer p(pointer);
  j.at(p.parent_pointer()).erase(p.back());
  return j;
}

TEST(JobNormalise, AFieldLeftOutIsItsDefaultWrittenIn) {
  const json full = defaults_written();
  ASSERT_NO_THROW(parse_job(full, "."));
  const std::string hash = job_hash(full);
  const std::vector<std::string> left_out = {
      "/case/gravity_cm_s2",
      "/case/particle_velocity/thermal_cm_s",
      "/case/particle_velocity/seed",
      "/case/particle_velocity",
      "/case/probes/pressure_drop/y1_dp",
      "/case/probes/pressure_drop/y2_dp",
      "/case/probes/pressure_drop",
      "/case/probes",
      "/case/boundaries/y_high/pressure_dyn_cm2",
      "/numerics/tolerances/linear",
      "/numerics/tolerances/filter",
      "/numerics/tolerances/steady",
      "/numerics/tolerances",
      "/numerics/max_iterations",
      "/numerics/stall_window",
      "/numerics/deposition/diffusivity",
      "/numerics/deposition/pre_deposition",
      "/numerics/deposition/sampling",
      "/numerics/deposition/integration",
  };
  json all_out = full;
  for (const auto& pointer : left_out) {
    const json omitted = without(full, pointer);
    EXPECT_NO_THROW(parse_job(omitted, ".")) << pointer;
    EXPECT_EQ(job_hash(omitted), hash) << pointer;
    if (all_out.contains(json::json_pointer(pointer))) all_out = without(all_out, pointer);
  }
  EXPECT_EQ(job_hash(all_out), hash) << all_out.dump();
  // The case name's default is "" (no name).
  json unnamed = full;
  unnamed["case"]["name"] = "";
  EXPECT_EQ(job_hash(without(full, "/case/name")), job_hash(unnamed));
  EXPECT_NE(job_hash(unnamed), hash);
}

TEST(JobNormalise, AValueOtherThanTheDefaultIsAnotherJob) {
  const json full = defaults_written();
  for (const auto& [pointer, value] : std::vector<std::pair<std::string, json>>{
           {"/case/gravity_cm_s2", json::array({0, -981, 0})},
           {"/case/probes/pressure_drop/y1_dp", 5},
           {"/case/particle_velocity/seed", 3},
           {"/case/boundaries/y_high/pressure_dyn_cm2", 1},
           {"/numerics/tolerances/filter", 1e-9},
           {"/numerics/stall_window", 100},
           {"/numerics/stall_remedy", "relax_correction"},
       }) {
    json changed = full;
    changed[json::json_pointer(pointer)] = value;
    EXPECT_NE(job_hash(changed), job_hash(full)) << pointer;
    EXPECT_NE(job_hash(without(changed, pointer.substr(0, pointer.rfind('/')))), job_hash(changed)) << pointer;
  }
}

TEST(JobNormalise, WallSpelledAsStringOrObjectIsOneJob) {
  json a = test::contract_job(), b = test::contract_job();
  a["case"]["boundaries"]["y_high"] = "wall";
  b["case"]["boundaries"]["y_high"] = {{"type", "wall"}};
  ASSERT_NO_THROW(parse_job(a, "."));
  ASSERT_NO_THROW(parse_job(b, "."));
  EXPECT_EQ(job_hash(a), job_hash(b));
}

TEST(JobNormalise, SscpGeneratorDefaults) {
  json a = test::contract_job();
  a["case"]["particles"]["generator"] = {{"kind", "sscp_like"},      {"seed", 1},    {"bed_height_dp", 100},
                                         {"solids_fraction", 0.5},   {"bubbles", 1}, {"bubble_radius_dp", 5}};
  json b = a;
  const std::string g = "/generator/allOf/2/then/properties/";
  b["case"]["particles"]["generator"]["bubble_solids_fraction"] = schema_default(g + "bubble_solids_fraction/default");
  b["case"]["particles"]["generator"]["emulsion"] = schema_default(g + "emulsion/default");
  EXPECT_EQ(job_hash(a), job_hash(b));
  // The lattice's relaxation sweeps: its default written or left out, one job.
  a["case"]["particles"]["generator"]["emulsion"] = "lattice";
  b["case"]["particles"]["generator"]["emulsion"] = "lattice";
  b["case"]["particles"]["generator"]["relaxation_sweeps"] = schema_default(g + "relaxation_sweeps/default");
  EXPECT_EQ(job_hash(a), job_hash(b));
  b["case"]["particles"]["generator"]["relaxation_sweeps"] = 5;
  EXPECT_NE(job_hash(a), job_hash(b));
}

// numerics.stall_remedy came after job hashes: its default is written by
// leaving it out, so every job from before it keeps its hash.
TEST(JobNormalise, StallRemedyNoneIsTheJobFromBeforeTheField) {
  const json before = defaults_written();
  json none = before;
  none["numerics"]["stall_remedy"] = schema_default("/stall_remedy/default");
  ASSERT_EQ(none["numerics"]["stall_remedy"], "none");
  EXPECT_EQ(job_hash(none), job_hash(before));
  EXPECT_EQ(job_hash(none), job_hash_before_defaults(before));
  EXPECT_EQ(job_hash(test::contract_job()), job_hash([] {
              json j = test::contract_job();
              j["numerics"]["stall_remedy"] = "none";
              return j;
            }()));
}

TEST(JobNormalise, TheHashIsShaOfTheCanonicalNormalisedDocument) {
  const json j = test::contract_job();
  EXPECT_EQ(job_hash(j), sha256_hex(canonical_json(normalised_job(j)) + "\n" + kSolverVersion));
  // A job with every default written is its own normalised form: its hash
  // did not change when defaults began to be filled in.
  EXPECT_EQ(canonical_json(normalised_job(defaults_written())), canonical_json(defaults_written()));
  EXPECT_EQ(job_hash(defaults_written()), job_hash_before_defaults(defaults_written()));
  EXPECT_NE(job_hash(j), job_hash_before_defaults(j));  // contract_job leaves stall_window out
}

}  // namespace
}  // namespace gridfree
