// SPDX-License-Identifier: GPL-3.0-or-later
// Step 12 — the quantity of a series (external cases, docs/EXTERNAL.md "The
// study"): an external case has one series per declared quantity, all over
// the same jobs, so the series table gains `quantity` ('' for the dp* of a
// physical case) and its UNIQUE key includes it. SQLite cannot change a
// UNIQUE constraint in place: the table is rebuilt as in step 5 (ids kept;
// the caller runs this inside the migration's transaction with foreign keys
// off, so dropping the old table does not cascade) and its index made again.
#include "store/schema_steps.h"

namespace gridfree {
namespace {

constexpr const char* kRebuildWithQuantity = R"sql(
CREATE TABLE series_before_v12 AS SELECT * FROM series;
DROP TABLE series;
CREATE TABLE series(
  id         INTEGER PRIMARY KEY,
  study_id   INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  position   INTEGER NOT NULL,
  case_name  TEXT NOT NULL,
  convection TEXT NOT NULL,
  fwhm_dp    REAL NOT NULL,
  drag       TEXT NOT NULL,
  deposition TEXT NOT NULL DEFAULT 'diffusion',
  status     TEXT NOT NULL DEFAULT 'queued'
             CHECK (status IN ('queued','running','done','failed','cancelled')),
  verdict    TEXT
             CHECK (verdict IS NULL OR verdict IN ('converged','pre-asymptotic','unreliable','insufficient_grids')),
  verdict_reasons TEXT,
  pre_deposition TEXT NOT NULL DEFAULT '',
  sampling       TEXT NOT NULL DEFAULT '',
  integration    TEXT NOT NULL DEFAULT '',
  diffusivity    TEXT NOT NULL DEFAULT '',
  steps          INTEGER NOT NULL DEFAULT 0,
  adaptive_status TEXT
             CHECK (adaptive_status IS NULL OR adaptive_status IN ('refining','target_met','target_not_reached')),
  adaptive_note TEXT,
  coverage_json TEXT,
  quantity       TEXT NOT NULL DEFAULT '',
  UNIQUE (study_id, case_name, convection, fwhm_dp, drag, deposition,
          pre_deposition, sampling, integration, diffusivity, steps, quantity)
);
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status,
                   verdict, verdict_reasons, pre_deposition, sampling, integration, diffusivity, steps,
                   adaptive_status, adaptive_note, coverage_json)
SELECT id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status,
       verdict, verdict_reasons, pre_deposition, sampling, integration, diffusivity, steps,
       adaptive_status, adaptive_note, coverage_json FROM series_before_v12;
DROP TABLE series_before_v12;
CREATE INDEX series_study_status ON series(study_id, status);
)sql";

}  // namespace

void migrate_series_quantity(Database& db) { db.exec(kRebuildWithQuantity); }

}  // namespace gridfree
