// SPDX-License-Identifier: GPL-3.0-or-later
// Schema steps 5 and 6 on a version-4 database with data: the series table
// is rebuilt with its transfer columns (filled from the jobs' documents, by
// the worker's rules) and the wider UNIQUE key; every row that references a
// series survives; the alignment table and views appear.
#include <gtest/gtest.h>

#include <filesystem>

#include "store/schema.h"
#include "store/store.h"
#include "scratch_dir.h"
#include "store_queries.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

using test_support::scalar;
using test_support::text;

// A version-4 database: one study, three series (fm18, an explicit
// diffusion transfer, centroid), a job each with a result, an uncertainty
// and an extrapolation.
void fill_v4(const fs::path& file) {
  Database db(file, true);
  migrate(db, 4);
  ASSERT_EQ(schema_version(db), 4);
  db.exec(R"sql(
INSERT INTO studies(id, name, definition_json) VALUES (1, 'old', '{}');
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status, verdict)
VALUES (10, 1, 0, 'PC1', 'superbee', 6, 'bvk', 'fm18', 'done', 'converged'),
       (11, 1, 1, 'PC1', 'superbee', 6, 'bvk', 'diffusion', 'done', 'pre-asymptotic'),
       (12, 1, 2, 'PC1', 'superbee', 6, 'bvk', 'centroid', 'queued', NULL);
INSERT INTO jobs(id, job_hash, spec_json, status, nx, ny, nz, cells, delta_star) VALUES
 (100, 'h100', '{"numerics":{"deposition":{"preset":"fm18","fwhm_dp":6}}}', 'done', 15, 100, 5, 7500, 2),
 (101, 'h101', '{"numerics":{"deposition":{"kind":"diffusion","diffusivity":"seed","integration":"steps","steps":16,"fwhm_dp":6}}}', 'done', 15, 100, 5, 7500, 2),
 (102, 'h102', '{"numerics":{"deposition":{"kind":"centroid","fwhm_dp":6}}}', 'queued', 15, 100, 5, 7500, 2);
INSERT INTO study_jobs(study_id, job_id, series_id, grid_index) VALUES (1, 100, 10, 0), (1, 101, 11, 0), (1, 102, 12, 0);
INSERT INTO results(job_id, status, dp_star, delta_star) VALUES (100, 'converged', 1017.5, 2), (101, 'converged', 1012.25, 2);
INSERT INTO uncertainties(series_id, job_id, delta_star, f, u, rde) VALUES (10, 100, 2, 1017.5, 3.5, 0.003);
INSERT INTO extrapolations(series_id, method, f0, chosen, status) VALUES (10, 'power', 1020.0, 1, 'ok');
)sql");
}

TEST(StoreMigration, Version4DatabaseGainsTransferColumnsWithItsDataIntact) {
  const auto file = test_support::fresh_db_path("store_migration_test", "v4");
  fill_v4(file);
  Store store(file, false);
  Database& db = store.db();
  EXPECT_EQ(schema_version(db), kSchemaVersion);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series"), 3);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM study_jobs"), 3);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM uncertainties WHERE series_id = 10"), 1);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM extrapolations WHERE series_id = 10"), 1);
  EXPECT_EQ(text(db, "SELECT verdict FROM series WHERE id = 11"), "pre-asymptotic");
  EXPECT_EQ(text(db, "SELECT status FROM series WHERE id = 12"), "queued");
  // Expanded as the worker expands them (docs/TRANSFER.md presets).
  EXPECT_EQ(text(db, "SELECT pre_deposition || '/' || sampling || '/' || integration || '/' || diffusivity || '/' || steps "
                     "FROM series WHERE id = 10"),
            "centroid/cell/steps/seed/8");
  EXPECT_EQ(text(db, "SELECT pre_deposition || '/' || sampling || '/' || integration || '/' || diffusivity || '/' || steps "
                     "FROM series WHERE id = 11"),
            "trilinear/trilinear/steps/seed/16");
  EXPECT_EQ(text(db, "SELECT pre_deposition || '/' || sampling || '/' || integration || '/' || diffusivity || '/' || steps "
                     "FROM series WHERE id = 12"),
            "centroid/cell///0");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM series WHERE pre_deposition = 'centroid'"), 2);
  // Views still read the rebuilt table.
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_results"), 3);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_series WHERE f0 = 1020.0"), 1);
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM v_alignment"), 0);
  EXPECT_EQ(text(db, "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
  EXPECT_EQ(scalar(db, "PRAGMA foreign_keys"), 1);  // on again after the migration
  // Deleting a series still cascades (the rebuilt table is the parent again).
  db.exec("DELETE FROM series WHERE id = 10");
  EXPECT_EQ(scalar(db, "SELECT COUNT(*) FROM uncertainties"), 0);
}

TEST(StoreMigration, UniqueKeyIncludesTheTransfer) {
  const auto file = test_support::fresh_db_path("store_migration_test", "unique");
  fs::remove(file);
  Store store(file);
  Database& db = store.db();
  db.exec("INSERT INTO studies(id, name, definition_json) VALUES (1, 's', '{}')");
  const std::string ins =
      "INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, pre_deposition, "
      "sampling) VALUES (1, 0, 'PC1', 'superbee', 6, 'bvk', 'x', ";
  db.exec(ins + "'trilinear', 'trilinear')");
  EXPECT_NO_THROW(db.exec(ins + "'centroid', 'trilinear')"));  // differs only in the transfer
  EXPECT_THROW(db.exec(ins + "'trilinear', 'trilinear')"), SqliteError);
}

}  // namespace
}  // namespace gridfree
