// SPDX-License-Identifier: GPL-3.0-or-later
// Job hashes of external jobs (docs/INTERFACE.md §2): the template's place
// and the collect section are not part of a job's identity; the template's
// contents, the variables, the command and the version are. And the
// hashes of physical jobs stay as they were before external jobs existed
// (pinned values).
#include <gtest/gtest.h>

#include "core/version.h"
#include "job/job_hash.h"
#include "contract_job.h"

namespace gridfree {
namespace {

using nlohmann::json;

json external_job() {
  return json::parse(R"({"schema": "gridfree/job/1",
    "case": {"name": "cavity", "external": {
      "template_dir": "/somewhere/cavity", "template_sha256": "ab12", "render": ["system/blockMeshDict"],
      "variables": {"N": 40, "dt": 0.0025}, "setup": ["export A=1"], "command": ["sh", "-c", "solve"],
      "version": "solver 1.0",
      "collect": {"quantities": {"f": {"units": "1", "file": "out.dat", "column": 1}}}}},
    "numerics": {"grid": {"level": 2, "h": 0.025, "cells": 1600}}})");
}

TEST(JobHashPinned, PhysicalJobHashesAreUnchanged) {
  // Computed before external jobs were added (gridfree-solver/5); a change
  // here reruns every finished job of every user's database.
  ASSERT_STREQ(kSolverVersion, "gridfree-solver/5");
  EXPECT_EQ(job_hash(test::contract_job()), "85141b65c4f8689df185a6f20fbbec382a6aefb11c575fc8d23f0e85a3f268d0");
  json small = test::contract_job();
  small["numerics"]["grid"]["cells"] = {10, 60, 4};
  small["numerics"]["deposition"] = {{"preset", "fm18"}, {"fwhm_dp", 3}};
  EXPECT_EQ(job_hash(small), "848d54d369b950460016fa8c9d2444e574c7fd48e79e5705ac22a0f7c824ff2a");
  json generated = test::contract_job();
  generated["case"]["particles"] = {{"generator", {{"kind", "sscp_like"}, {"seed", 7}, {"bed_height_dp", 20},
                                                   {"solids_fraction", 0.58}, {"bubbles", 1}, {"bubble_radius_dp", 3}}}};
  EXPECT_EQ(job_hash(generated), "6103df73661c54fbd472e8d5035cb02a65f952b68cd054a406629543a21f6d79");
}

TEST(JobHashExternal, TemplatePlaceAndCollectAreNotPartOfTheIdentity) {
  const std::string base = job_hash(external_job());
  json moved = external_job();
  moved["case"]["external"]["template_dir"] = "/elsewhere/cavity";
  EXPECT_EQ(job_hash(moved), base);
  json recollected = external_job();
  recollected["case"]["external"]["collect"]["quantities"]["f"]["column"] = 2;
  recollected["case"]["external"]["collect"]["failure_patterns"] = {"FATAL"};
  EXPECT_EQ(job_hash(recollected), base);
}

TEST(JobHashExternal, TemplateVariablesCommandAndVersionAre) {
  const std::string base = job_hash(external_job());
  const auto changed = [](auto edit) {
    json j = external_job();
    edit(j["case"]["external"]);
    return job_hash(j);
  };
  EXPECT_NE(changed([](json& e) { e["template_sha256"] = "ab13"; }), base);
  EXPECT_NE(changed([](json& e) { e["variables"]["dt"] = 0.002; }), base);
  EXPECT_NE(changed([](json& e) { e["command"][2] = "solve2"; }), base);
  EXPECT_NE(changed([](json& e) { e["setup"] = json::array(); }), base);
  EXPECT_NE(changed([](json& e) { e["version"] = "solver 1.1"; }), base);
  EXPECT_NE(changed([](json& e) { e["render"] = json::array(); }), base);
  json grid = external_job();
  grid["numerics"]["grid"]["h"] = 0.02;
  EXPECT_NE(job_hash(grid), base);
  // No physical defaults are filled into an external job: the text hashed is its own.
  json identity = external_job();
  identity["case"]["external"].erase("template_dir");
  identity["case"]["external"].erase("collect");
  EXPECT_EQ(base, sha256_hex(canonical_json(identity) + "\n" + kSolverVersion));
}

}  // namespace
}  // namespace gridfree
