// SPDX-License-Identifier: GPL-3.0-or-later
// Schema step 12 on a version-11 database with data: the series table is
// rebuilt with `quantity` ('' for existing series) in its UNIQUE key; every
// column, index and referencing row survives, and two series that differ
// only by quantity (an external case's) can then coexist.
#include <gtest/gtest.h>

#include <filesystem>

#include "scratch_dir.h"
#include "store/schema.h"
#include "store/store.h"
#include "store_queries.h"

namespace gridfree {
namespace {

using test_support::scalar;
using test_support::text;

void fill_v11(const std::filesystem::path& file) {
  Database db(file, true);
  migrate(db, 11);
  ASSERT_EQ(schema_version(db), 11);
  db.exec(R"sql(
INSERT INTO studies(id, name, definition_json) VALUES (1, 'old', '{}');
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status, verdict,
                   verdict_reasons, sampling, steps, adaptive_status, adaptive_note, coverage_json)
VALUES (10, 1, 0, 'PC1', 'superbee', 6, 'bvk', 'fm18', 'done', 'converged', '["ok"]', 'cell', 8, 'target_met',
        'met', '{"c":1}');
INSERT INTO jobs(id, job_hash, spec_json, status, nx, ny, nz, cells, delta_star) VALUES
 (100, 'h100', '{}', 'done', 15, 100, 5, 7500, 2);
INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES (1, 100, 10, 0);
INSERT INTO results(job_id, status, dp_star, delta_star) VALUES (100, 'converged', 1017.5, 2);
INSERT INTO extrapolations(series_id, method, f0, chosen, status) VALUES (10, 'power', 1020.0, 1, 'ok');
)sql");
}

TEST(StoreQuantityMigration, Version11SeriesKeepEverythingAndGainAQuantityInTheKey) {
  const auto file = test_support::fresh_db_path("store_quantity_migration_test", "v11");
  fill_v11(file);
  Store store(file, false);
  Database& db = store.db();
  EXPECT_EQ(schema_version(db), kSchemaVersion);
  EXPECT_EQ(text(db, "SELECT quantity FROM series WHERE id = 10"), "");
  EXPECT_EQ(text(db, "SELECT verdict || verdict_reasons || sampling || steps || adaptive_status || adaptive_note || "
                     "coverage_json FROM series WHERE id = 10"),
            "converged[\"ok\"]cell8target_metmet{\"c\":1}");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM study_jobs WHERE series_id = 10"), 1);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM extrapolations WHERE series_id = 10"), 1);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM sqlite_master WHERE type = 'index' AND name = 'series_study_status'"), 1);
  // Two quantities of one external case: distinct series; the same quantity twice is refused.
  db.exec("INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, quantity) "
          "VALUES (1, 1, 'cavity', '', 0, '', '', 'kinetic_energy'), (1, 2, 'cavity', '', 0, '', '', 'ux_probe')");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series WHERE case_name = 'cavity'"), 2);
  EXPECT_THROW(db.exec("INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, "
                       "quantity) VALUES (1, 3, 'cavity', '', 0, '', '', 'ux_probe')"),
               SqliteError);
  // Deleting the study still cascades to its series (the foreign key survived the rebuild).
  db.exec("PRAGMA foreign_keys = ON");
  db.exec("DELETE FROM extrapolations; DELETE FROM results; DELETE FROM study_jobs; DELETE FROM studies WHERE id = 1");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series"), 0);
}

}  // namespace
}  // namespace gridfree
