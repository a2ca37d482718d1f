// SPDX-License-Identifier: GPL-3.0-or-later
// Schema step 11 (store/schema_job_hashes.cpp) on a version-10 database whose
// jobs carry the hashes of before defaults were filled in: every job of this
// solver version is rehashed from its stored document, so a study that
// writes the defaults out finds the finished job (nothing solved twice);
// two jobs that differ only by a default left out become one, the finished
// one kept with every study's link; other solver versions' jobs keep theirs.
#include <gtest/gtest.h>

#include <filesystem>

#include "contract_job.h"
#include "job/job_hash.h"
#include "store/schema.h"
#include "store/store.h"
#include "scratch_dir.h"
#include "store_queries.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::scalar;
using test_support::text;

// The contract job with gravity left out, and with it written.
json gravity_left_out() {
  json j = test::contract_job();
  j["case"].erase("gravity_cm_s2");
  return j;
}
json gravity_written() { return test::contract_job(); }
// A job this migration does not know the old hash of (as of another solver version).
json other_job() {
  json j = gravity_left_out();
  j["case"]["name"] = "other";
  return j;
}

// One study `name` with one series linking job `job_id`.
std::string study_sql(int study_id, const std::string& name, int series_id, int job_id) {
  const std::string s = std::to_string(study_id), se = std::to_string(series_id), j = std::to_string(job_id);
  return "INSERT INTO studies(id, name, definition_json) VALUES (" + s + ", '" + name + "', '{}');" +
         "INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag) VALUES (" + se + ", " + s +
         ", 0, 'PC1', 'superbee', 6, 'bvk');" + "INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES (" +
         s + ", " + j + ", " + se + ", 0);";
}

std::string job_sql(int id, const std::string& hash, const json& doc, const std::string& status) {
  return "INSERT INTO jobs(id, job_hash, spec_json, status, nx, ny, nz, cells) VALUES (" + std::to_string(id) + ", '" +
         hash + "', '" + doc.dump() + "', '" + status + "', 30, 200, 10, 60000);";
}

// A version-10 database as this solver version made it before step 11.
fs::path old_database(const std::string& name, const std::string& rows) {
  const auto file = test_support::fresh_db_path("store_job_hash_migration_test", name);
  Database db(file, true);
  migrate(db, 10);
  db.exec(rows);
  return file;
}

TEST(StoreJobHashMigration, AFinishedJobIsFoundUnderItsNewHashAndNotSolvedAgain) {
  ASSERT_NE(job_hash_before_defaults(gravity_left_out()), job_hash(gravity_left_out()));
  const auto file = old_database(
      "found", job_sql(1, job_hash_before_defaults(gravity_left_out()), gravity_left_out(), "done") +
                   "INSERT INTO results(job_id, status, dp_star) VALUES (1, 'converged', 1017.5);" +
                   study_sql(1, "old", 10, 1) +
                   job_sql(2, "another-solver-version", other_job(), "done"));
  Store store(file, false);
  EXPECT_EQ(schema_version(store.db()), kSchemaVersion);
  EXPECT_EQ(text(store, "SELECT job_hash FROM jobs WHERE id = 1"), job_hash(gravity_left_out()));
  EXPECT_EQ(text(store, "SELECT job_hash FROM jobs WHERE id = 2"), "another-solver-version");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE kind = 'rehash' AND job_id = 1"), 1);
  // A study that writes gravity's default out: its job is the finished one.
  Study s;
  s.name = "explicit";
  s.definition = {{"name", "explicit"}};
  ExpandedStudy ex;
  ex.series.push_back(SeriesKey{"PC1", "superbee", 6.0, "bvk", "diffusion"});
  StudyJob j;
  j.cells = {30, 200, 10};
  j.doc = gravity_written();
  j.hash = job_hash(j.doc);
  ex.jobs.push_back(j);
  const SubmitResult r = store.submit(s, ex, false);
  EXPECT_EQ(r.jobs_new, 0u);
  EXPECT_EQ(r.jobs_reused, 1u);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'queued'"), 0);
}

TEST(StoreJobHashMigration, TwoSpellingsOfOneJobBecomeOneKeepingTheFinishedOne) {
  const auto file = old_database(
      "merged", job_sql(1, job_hash_before_defaults(gravity_written()), gravity_written(), "queued") +
                    study_sql(1, "written", 10, 1) +
                    job_sql(2, job_hash_before_defaults(gravity_left_out()), gravity_left_out(), "done") +
                    "INSERT INTO results(job_id, status, dp_star) VALUES (2, 'converged', 1017.5);" +
                    "INSERT INTO events(job_id, kind, message) VALUES (2, 'result', 'converged');" +
                    study_sql(2, "left_out", 20, 2) +
                    "INSERT INTO uncertainties(series_id, job_id, delta_star, f, u, rde) VALUES (20, 2, 2, 1017.5, 1, 0.001);");
  Store store(file, false);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 1);
  EXPECT_EQ(scalar(store, "SELECT id FROM jobs"), 2);
  EXPECT_EQ(text(store, "SELECT status || ' ' || job_hash FROM jobs"), "done " + job_hash(gravity_written()));
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM study_jobs WHERE job_id = 2"), 2);  // both studies link it
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM uncertainties WHERE job_id = 2"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE job_id NOT IN (SELECT id FROM jobs)"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE kind = 'rehash'"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM v_results WHERE result_status = 'converged'"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
  EXPECT_EQ(text(store, "PRAGMA integrity_check"), "ok");
}

}  // namespace
}  // namespace gridfree

namespace gridfree {
namespace {

// An sscp_like job of before the random emulsion (no "emulsion": its bed was
// the lattice) keeps a lattice identity: it never answers for the random
// bed the same text now means, and its spec says lattice for a rerun.
TEST(StoreJobHashMigration, ALatticeEraSscpJobStaysALatticeJob) {
  json old_doc = test::contract_job();
  old_doc["case"]["particles"] = {{"generator", {{"kind", "sscp_like"}, {"seed", 1}}}};
  const auto file = test_support::fresh_db_path("store_job_hash_migration_test", "lattice");
  {
    Database db(file, true);
    migrate(db, 10);
    db.exec("INSERT INTO jobs(id, job_hash, spec_json, status, nx, ny, nz, cells) VALUES (1, '" +
            job_hash_before_defaults(old_doc) + "', '" + old_doc.dump() + "', 'done', 30, 200, 10, 60000);");
  }
  Store store(file, false);
  json lattice = old_doc;
  lattice["case"]["particles"]["generator"]["emulsion"] = "lattice";
  EXPECT_EQ(text(store, "SELECT job_hash FROM jobs WHERE id = 1"), job_hash(lattice));
  EXPECT_NE(text(store, "SELECT job_hash FROM jobs WHERE id = 1"), job_hash(old_doc));  // old_doc now means random
  EXPECT_EQ(json::parse(text(store, "SELECT spec_json FROM jobs WHERE id = 1")), lattice);
}

}  // namespace
}  // namespace gridfree
