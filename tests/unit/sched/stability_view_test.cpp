// SPDX-License-Identifier: GPL-3.0-or-later
// v_stability (store/stability_view.h): one row per grid with the outcome
// word the report's stability map gives the same grid (report/stability_map.h
// grid_outcome), for every status, the worker's outcome field and the
// reasons that decide stalled and timed_out; alignment variants left out;
// created at open for a database at the current version that lacks it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "report/stability_map.h"
#include "scratch_dir.h"
#include "store/schema.h"
#include "store/sqlite.h"

namespace gridfree {
namespace {

struct StabilityCase {
  std::string job_status, result_status, reason, worker_outcome, expected;
};

const std::vector<StabilityCase> kStabilityCases = {
    {"done", "converged", "", "converged", "converged"},
    {"done", "not_converged", "not converged after 400 iterations", "stalled", "stalled"},
    {"done", "not_converged", "not converged after stalling for 200 iterations at iteration 229", "", "stalled"},
    {"done", "not_converged", "not converged after 5000 iterations", "iteration_cap", "iteration_cap"},
    {"done", "not_converged", "not converged after 5000 iterations", "", "iteration_cap"},
    {"done", "diverged", "diverged at iteration 12", "diverged", "diverged"},
    {"done", "invalid", "centroid deposition puts solids fraction eps_s = 2.09", "invalid", "invalid"},
    {"failed", "failed", "timed out: 600 s (after 2 attempts)", "", "timed_out"},
    {"failed", "failed", "worker exit 1 (after 2 attempts)", "", "failed"},
    {"queued", "", "", "", "pending"},
    {"running", "", "", "", "pending"},
    {"cancelled", "", "", "", "cancelled"},
};

void fill_stability_db(Database& db) {
  db.exec("INSERT INTO studies(id, name, definition_json) VALUES (1, 'st', '{}')");
  db.exec("INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag) "
          "VALUES (1, 1, 0, 'bed', 'superbee', 6, 'bvk')");
  for (std::size_t i = 0; i < kStabilityCases.size(); ++i) {
    const auto& c = kStabilityCases[i];
    const long long id = static_cast<long long>(i) + 1;
    db.prepare("INSERT INTO jobs(id, job_hash, spec_json, status, delta_star) VALUES (?, ?, '{}', ?, ?)")
        .bind_all(id, "h" + std::to_string(id), c.job_status, 1.0 / double(id))
        .run();
    db.prepare("INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES (1, ?, 1, ?)")
        .bind_all(id, id)
        .run();
    if (c.result_status.empty()) continue;
    const std::string json =
        c.worker_outcome.empty() ? "{\"status\": \"" + c.result_status + "\"}"
                                 : "{\"status\": \"" + c.result_status + "\", \"outcome\": \"" + c.worker_outcome + "\"}";
    db.prepare("INSERT INTO results(job_id, status, reason, result_json, iterations) VALUES (?, ?, ?, ?, 7)")
        .bind_all(id, c.result_status, c.reason, json)
        .run();
  }
  // An alignment variant: not a grid of the series' map.
  db.exec("INSERT INTO jobs(id, job_hash, spec_json, status) VALUES (100, 'variant', '{}', 'queued')");
  db.exec("INSERT INTO study_jobs(study_id, job_id, series_id, grid_index, alignment_only) VALUES (1, 100, 1, 99, 1)");
}

TEST(StabilityView, GivesTheReportsOutcomeForEveryStatusAndLeavesVariantsOut) {
  const auto dir = test_support::fresh_scratch_dir("stability_view_test", "words");
  Database db(dir / "g.sqlite", true);
  migrate(db);
  fill_stability_db(db);
  auto st = db.prepare("SELECT job_id, outcome FROM v_stability ORDER BY job_id");
  std::size_t rows = 0;
  while (st.step()) {
    const long long id = st.as_int(0);
    ASSERT_GE(id, 1);
    ASSERT_LE(id, static_cast<long long>(kStabilityCases.size())) << "an alignment variant in the view";
    const auto& c = kStabilityCases[static_cast<std::size_t>(id - 1)];
    EXPECT_EQ(st.as_text(1), c.expected) << c.result_status << " / " << c.reason;
    const std::string status = c.result_status.empty() ? c.job_status : c.result_status;
    EXPECT_EQ(grid_outcome(status, c.reason, c.worker_outcome), c.expected) << "the report disagrees";
    ++rows;
  }
  EXPECT_EQ(rows, kStabilityCases.size());
}

TEST(StabilityView, IsCreatedAtOpenWhenADatabaseOfThisVersionLacksIt) {
  const auto dir = test_support::fresh_scratch_dir("stability_view_test", "reopen");
  {
    Database db(dir / "g.sqlite", true);
    migrate(db);
    db.exec("DROP VIEW v_stability");
  }
  Database db(dir / "g.sqlite", true);
  migrate(db);
  auto st = db.prepare("SELECT COUNT(*) FROM sqlite_master WHERE type = 'view' AND name = 'v_stability'");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.as_int(0), 1);
  EXPECT_EQ(schema_version(db), kSchemaVersion);
}

}  // namespace
}  // namespace gridfree
