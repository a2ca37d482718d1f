// SPDX-License-Identifier: GPL-3.0-or-later
// The "default" of every optional job field in schemas/job.schema.json (what
// users read) is the value the parser uses when the field is left out.
#include <gtest/gtest.h>

#include <cmath>

#include "contract_job.h"
#include "core/embedded_schemas.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

json job_schema_definitions() { return json::parse(embedded_schema("job.schema"))["definitions"]; }

TEST(SchemaDefaults, AreTheParserDefaults) {
  const json d = job_schema_definitions();
  json j = test::contract_job();
  j["case"].erase("gravity_cm_s2");
  j["case"].erase("particle_velocity");
  j["case"].erase("probes");
  j["case"]["boundaries"]["y_high"].erase("pressure_dyn_cm2");
  j["numerics"].erase("tolerances");
  j["numerics"].erase("max_iterations");
  j["numerics"]["deposition"].erase("diffusivity");
  const JobSpec job = parse_job(j, ".");

  const json& tol = d["tolerances"]["properties"];
  EXPECT_EQ(job.numerics.tolerances.linear, tol["linear"]["default"].get<double>());
  EXPECT_EQ(job.numerics.tolerances.filter, tol["filter"]["default"].get<double>());
  EXPECT_EQ(job.numerics.tolerances.steady, tol["steady"]["default"].get<double>());
  EXPECT_EQ(job.numerics.max_iterations, d["max_iterations"]["default"].get<int>());
  EXPECT_FALSE(j["numerics"].contains("stall_window"));
  EXPECT_EQ(job.numerics.stall_window, d["stall_window"]["default"].get<int>());
  EXPECT_FALSE(j["numerics"].contains("stall_remedy"));
  EXPECT_EQ(d["stall_remedy"]["default"].get<std::string>(), "none");
  EXPECT_FALSE(job.numerics.relax_stalled_correction);
  const auto gravity = d["case"]["properties"]["gravity_cm_s2"]["default"].get<std::array<double, 3>>();
  EXPECT_EQ(job.case_spec.gravity_cm_s2, gravity);
  EXPECT_EQ(job.case_spec.particle_velocity.thermal_cm_s,
            d["particle_velocity"]["properties"]["thermal_cm_s"]["default"].get<double>());
  const json& probe = d["probes"]["properties"]["pressure_drop"]["properties"];
  EXPECT_EQ(job.case_spec.probes.y1_dp, probe["y1_dp"]["default"].get<double>());
  EXPECT_EQ(job.case_spec.probes.y2_dp, probe["y2_dp"]["default"].get<double>());
  EXPECT_EQ(d["deposition"]["properties"]["diffusivity"]["default"].get<std::string>(),
            filter_diffusivity_name(job.numerics.deposition.diffusivity));
  // The outlet pressure: the pressure_outflow branch of y_boundary.
  double outlet_default = NAN;
  for (const auto& branch : d["y_boundary"]["else"]["allOf"])
    if (branch["then"]["properties"].contains("pressure_dyn_cm2"))
      outlet_default = branch["then"]["properties"]["pressure_dyn_cm2"]["default"].get<double>();
  EXPECT_EQ(job.case_spec.boundaries[1][1].pressure_dyn_cm2, outlet_default);
}

}  // namespace
}  // namespace gridfree
