// SPDX-License-Identifier: GPL-3.0-or-later
// Step 5 — transfer columns of a series (feature: transfer methods as study
// factors, docs/DATABASE.md). The series table gains the expanded transfer
// of its jobs: pre_deposition, sampling, integration, diffusivity ('' where
// a field does not apply: no filter) and steps (0 unless integration is
// 'steps'); the UNIQUE key includes them. SQLite cannot change a UNIQUE
// constraint in place, so the table is rebuilt (ids kept; the caller runs
// this inside the migration's transaction with foreign keys off, so that
// dropping the old table does not cascade) and the columns of existing
// series are filled from one of their job documents.
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "store/schema_steps.h"
#include "study/study_transfer.h"

namespace gridfree {
namespace {

constexpr const char* kRebuild = R"sql(
CREATE TABLE series_before_v5 AS SELECT * FROM series;
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
  UNIQUE (study_id, case_name, convection, fwhm_dp, drag, deposition,
          pre_deposition, sampling, integration, diffusivity, steps)
);
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status,
                   verdict, verdict_reasons)
SELECT id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status,
       verdict, verdict_reasons FROM series_before_v5;
DROP TABLE series_before_v5;
)sql";

}  // namespace

void migrate_series_transfer(Database& db) {
  db.exec(kRebuild);
  // One job document per series gives its transfer.
  auto list = db.prepare(
      "SELECT se.id, (SELECT j.spec_json FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
      "WHERE sj.series_id = se.id ORDER BY sj.grid_index LIMIT 1) FROM series se");
  std::vector<std::pair<long long, std::string>> rows;
  while (list.step()) rows.emplace_back(list.as_int(0), list.as_text(1));
  auto update = db.prepare(
      "UPDATE series SET pre_deposition = ?, sampling = ?, integration = ?, diffusivity = ?, steps = ? WHERE id = ?");
  for (const auto& [id, spec] : rows) {
    if (spec.empty()) continue;  // a series without jobs: nothing to read, columns stay ''
    const auto doc = nlohmann::json::parse(spec, nullptr, false);
    if (doc.is_discarded() || !doc.contains("numerics") || !doc["numerics"].contains("deposition")) continue;
    TransferColumns c;
    try {
      c = transfer_columns(doc["numerics"]["deposition"]);
    } catch (const InputError&) {
      continue;  // a document this worker no longer reads: columns stay ''
    }
    update.reset();
    update.bind_all(c.pre_deposition, c.sampling, c.integration, c.diffusivity, c.steps, id).run();
  }
}

}  // namespace gridfree
