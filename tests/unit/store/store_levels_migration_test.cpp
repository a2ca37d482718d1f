// SPDX-License-Identifier: GPL-3.0-or-later
// Schema step 13 on a version-12 database with a physical and an external
// series: the series table is rebuilt with `levels` ('{}' for existing
// series) in its key; ids, job hashes, links and results survive; the
// external series' particle-bed columns become NULL (in the table and in
// v_series / v_results), the physical one's stay; series differing only by
// levels coexist and the views read quantity, levels and the value.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "scratch_dir.h"
#include "store/schema.h"
#include "store/store.h"
#include "store_queries.h"

namespace gridfree {
namespace store_levels_migration_test {

using test_support::scalar;
using test_support::text;

void fill_v12_with_external(const std::filesystem::path& file) {
  Database db(file, true);
  migrate(db, 12);
  ASSERT_EQ(schema_version(db), 12);
  // As gridfree before step 13 stored them: an external series with '' and 0
  // in the particle-bed columns.
  db.exec(R"sql(
INSERT INTO studies(id, name, definition_json) VALUES (1, 'bed', '{}'), (2, 'cavity', '{}');
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status, verdict, quantity)
VALUES (10, 1, 0, 'PC1', 'superbee', 6, 'bvk', 'diffusion', 'done', 'converged', ''),
       (20, 2, 0, 'cavity', '', 0, '', '', 'done', 'converged', 'mean_u2');
INSERT INTO jobs(id, job_hash, spec_json, status, nx, ny, nz, cells, delta_star) VALUES
 (100, 'h100', '{}', 'done', 15, 100, 5, 7500, 2),
 (200, 'h200', '{"case": {"external": {}}}', 'done', 400, 1, 1, 400, 0.005);
INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES (1, 100, 10, 0), (2, 200, 20, 0);
INSERT INTO results(job_id, status, dp_star, delta_star, result_json) VALUES
 (100, 'converged', 1017.5, 2, '{}'),
 (200, 'converged', NULL, 0.005, '{"quantities": {"mean_u2": 0.0123}}');
INSERT INTO extrapolations(series_id, method, f0, chosen, status) VALUES (10, 'power', 1020.0, 1, 'ok'),
 (20, 'power', 0.0125, 1, 'ok');
INSERT INTO uncertainties(series_id, job_id, delta_star, f, u, rde) VALUES (20, 200, 0.005, 0.0123, 0.0002, 0.016);
)sql");
}

TEST(StoreLevelsMigration, Version12SeriesKeepIdsAndResultsAndExternalOnesLoseTheBedColumns) {
  const auto file = test_support::fresh_db_path("store_levels_migration_test", "v12");
  fill_v12_with_external(file);
  Store store(file, false);
  Database& db = store.db();
  EXPECT_EQ(schema_version(db), kSchemaVersion);
  // Ids, hashes, links, results and extrapolations kept.
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series WHERE id IN (10, 20)"), 2);
  EXPECT_EQ(text(db, "SELECT group_concat(job_hash) FROM (SELECT job_hash FROM jobs ORDER BY id)"), "h100,h200");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM study_jobs WHERE series_id IN (10, 20)"), 2);
  EXPECT_EQ(text(db, "SELECT f0 FROM v_series WHERE series_id = 20"), "0.0125");
  EXPECT_EQ(text(db, "SELECT levels FROM series WHERE id = 20"), "{}");
  // The physical series keeps its factors; the external one has none of the bed's.
  EXPECT_EQ(text(db, "SELECT convection || fwhm_dp || drag || deposition FROM v_series WHERE series_id = 10"),
            "superbee6.0bvkdiffusion");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_series WHERE series_id = 20 AND convection IS NULL AND fwhm_dp IS "
                       "NULL AND drag IS NULL AND deposition IS NULL"),
            1);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_results WHERE series_id = 20 AND convection IS NULL AND fwhm_dp IS "
                       "NULL AND drag IS NULL AND deposition IS NULL AND dp_star IS NULL"),
            1);
  // v_results reads each series' own quantity as `value`.
  EXPECT_EQ(text(db, "SELECT quantity || ' ' || value FROM v_results WHERE series_id = 20"), "mean_u2 0.0123");
  EXPECT_EQ(text(db, "SELECT value FROM v_results WHERE series_id = 10"), "1017.5");
  // Two configurations of one external case: distinct series; the same one twice is refused.
  db.exec("INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, quantity, levels) "
          "VALUES (2, 1, 'cavity', NULL, NULL, NULL, NULL, 'mean_u2', '{\"scheme\":\"QUICK\"}')");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series WHERE case_name = 'cavity'"), 2);
  EXPECT_THROW(db.exec("INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, "
                       "quantity, levels) VALUES (2, 2, 'cavity', NULL, NULL, NULL, NULL, 'mean_u2', "
                       "'{\"scheme\":\"QUICK\"}')"),
               SqliteError);
  // Deleting a study still cascades to its series (the foreign key survived the rebuild).
  db.exec("PRAGMA foreign_keys = ON");
  db.exec("DELETE FROM extrapolations; DELETE FROM uncertainties; DELETE FROM results; DELETE FROM study_jobs; "
          "DELETE FROM studies WHERE id = 2");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series"), 1);
}

// The ensemble view averages each configuration (quantity and levels
// included) over the instances, with NULL particle-bed columns.
TEST(StoreLevelsMigration, EnsembleBudgetGroupsExternalConfigurationsByQuantityAndLevels) {
  const auto file = test_support::fresh_db_path("store_levels_migration_test", "ensemble");
  Store store(file, true);
  Database& db = store.db();
  db.exec(R"sql(
INSERT INTO studies(id, name, definition_json) VALUES (1, 'e', '{}');
INSERT INTO ensembles(study_id, name, case_name) VALUES (1, 'inst', 'a'), (1, 'inst', 'b');
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, quantity, levels) VALUES
 (1, 1, 0, 'a', NULL, NULL, NULL, NULL, 'q', '{"s":"up"}'), (2, 1, 1, 'b', NULL, NULL, NULL, NULL, 'q', '{"s":"up"}'),
 (3, 1, 2, 'a', NULL, NULL, NULL, NULL, 'q', '{"s":"lin"}'), (4, 1, 3, 'b', NULL, NULL, NULL, NULL, 'q', '{"s":"lin"}'),
 (5, 1, 4, 'a', NULL, NULL, NULL, NULL, 'r', '{"s":"up"}'), (6, 1, 5, 'b', NULL, NULL, NULL, NULL, 'r', '{"s":"up"}');
INSERT INTO jobs(id, job_hash, spec_json) VALUES (1, 'j1', '{}'), (2, 'j2', '{}'), (3, 'j3', '{}'), (4, 'j4', '{}');
INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES
 (1, 1, 1, 0), (1, 2, 2, 0), (1, 3, 3, 0), (1, 4, 4, 0), (1, 1, 5, 0), (1, 2, 6, 0);
INSERT INTO extrapolations(series_id, method, f0, chosen) VALUES
 (1, 'power', 1.0, 1), (2, 'power', 3.0, 1), (3, 'power', 10.0, 1), (4, 'power', 20.0, 1), (5, 'power', 7.0, 1),
 (6, 'power', 7.0, 1);
)sql");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_ensemble_budget"), 3);
  // Mean of 1 and 3 is 2, sample sd sqrt(2); of 10 and 20: 15 and sqrt(50).
  EXPECT_EQ(text(db, "SELECT f0_mean || ' ' || instances FROM v_ensemble_budget WHERE quantity = 'q' AND levels = "
                     "'{\"s\":\"up\"}'"),
            "2.0 2");
  EXPECT_EQ(text(db, "SELECT f0_mean FROM v_ensemble_budget WHERE quantity = 'q' AND levels = '{\"s\":\"lin\"}'"),
            "15.0");
  EXPECT_NEAR(std::stod(text(db, "SELECT f0_sd FROM v_ensemble_budget WHERE quantity = 'q' AND levels = "
                                 "'{\"s\":\"lin\"}'")),
              std::sqrt(50.0), 1e-12);
  EXPECT_EQ(text(db, "SELECT f0_mean || ' ' || f0_sd FROM v_ensemble_budget WHERE quantity = 'r'"), "7.0 0.0");
}

}  // namespace store_levels_migration_test
}  // namespace gridfree
