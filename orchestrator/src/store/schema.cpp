// SPDX-License-Identifier: GPL-3.0-or-later
// Schema version 11 (step 1: the tables; 2: nominal Δ*, v_series; 3: Slurm queue
// state; 4: series verdicts; 5: series transfer columns; 6: alignment check;
// 7: adaptive series; 8: ensembles; 9: indexes for
// the scheduler at ensemble scale; 10: the series' coverage self-check;
// 11: job hashes of the normalised job document; 12: series.quantity for
// external cases; 13: series.levels, an external series' factor levels, and
// NULL particle-bed factors for external series). Status words (docs/INTERFACE.md §5):
//   jobs, studies: queued | running | done | failed | cancelled
//   series:        queued | running | done | failed | cancelled
// A job's `owner` names the process that claimed it ("host:pid:start"),
// so a restart can tell a live claim from a stale one.
#include "store/schema.h"

#include "store/schema_steps.h"

#include <algorithm>
#include <string>

#include "core/input_error.h"
#include "core/version.h"
#include "store/database_file.h"
#include "store/journal_mode.h"
#include "store/schema_ensembles.h"
#include "store/stability_view.h"

namespace gridfree {
namespace {

constexpr const char* kV1 = R"sql(
CREATE TABLE studies(
  id              INTEGER PRIMARY KEY,
  name            TEXT NOT NULL UNIQUE,
  definition_json TEXT NOT NULL,
  status          TEXT NOT NULL DEFAULT 'queued'
                  CHECK (status IN ('queued','running','done','failed','cancelled')),
  submitted_at    TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')),
  finished_at     TEXT,
  design          TEXT,
  extrapolation_json TEXT
);
CREATE TABLE jobs(
  id          INTEGER PRIMARY KEY,
  job_hash    TEXT NOT NULL UNIQUE,
  spec_json   TEXT NOT NULL,
  status      TEXT NOT NULL DEFAULT 'queued'
              CHECK (status IN ('queued','running','done','failed','cancelled')),
  attempts    INTEGER NOT NULL DEFAULT 0,
  started_at  TEXT,
  finished_at TEXT,
  error       TEXT,
  owner       TEXT,
  nx INTEGER, ny INTEGER, nz INTEGER,
  cells       INTEGER,
  delta_star  REAL,
  result_path TEXT,
  external_id TEXT
);
CREATE INDEX jobs_status ON jobs(status);
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
  UNIQUE (study_id, case_name, convection, fwhm_dp, drag, deposition)
);
CREATE TABLE study_jobs(
  study_id   INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  job_id     INTEGER NOT NULL REFERENCES jobs(id),
  series_id  INTEGER NOT NULL REFERENCES series(id) ON DELETE CASCADE,
  grid_index INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (series_id, job_id)
);
CREATE INDEX study_jobs_job ON study_jobs(job_id);
CREATE INDEX study_jobs_study ON study_jobs(study_id);
CREATE TABLE results(
  job_id      INTEGER PRIMARY KEY REFERENCES jobs(id),
  status      TEXT NOT NULL
              CHECK (status IN ('converged','not_converged','diverged','invalid','failed')),
  dp_star     REAL,
  delta_star  REAL,
  nx INTEGER, ny INTEGER, nz INTEGER,
  iterations  INTEGER,
  wall_s      REAL,
  cpu_s       REAL,
  peak_rss_mb REAL,
  result_json TEXT,
  reason      TEXT,
  recorded_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))
);
CREATE TABLE extrapolations(
  series_id  INTEGER NOT NULL REFERENCES series(id) ON DELETE CASCADE,
  method     TEXT NOT NULL,
  f0 REAL, p REAL, c REAL, c1 REAL, c2 REAL,
  sigma_re   REAL,
  data_range REAL,
  fs         REAL,
  chosen     INTEGER NOT NULL DEFAULT 0,
  status     TEXT,
  detail_json TEXT,
  PRIMARY KEY (series_id, method)
);
CREATE TABLE uncertainties(
  series_id  INTEGER NOT NULL REFERENCES series(id) ON DELETE CASCADE,
  job_id     INTEGER NOT NULL REFERENCES jobs(id),
  delta_star REAL,
  f          REAL,
  u          REAL,
  rde        REAL,
  PRIMARY KEY (series_id, job_id)
);
CREATE TABLE events(
  id       INTEGER PRIMARY KEY,
  at       TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')),
  study_id INTEGER,
  job_id   INTEGER,
  kind     TEXT NOT NULL,
  message  TEXT
);
CREATE VIEW v_results AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       sj.grid_index  AS grid_index,
       j.id           AS job_id,
       j.job_hash     AS job_hash,
       j.status       AS job_status,
       j.attempts     AS attempts,
       COALESCE(r.delta_star, j.delta_star) AS delta_star,
       COALESCE(r.nx, j.nx) AS nx,
       COALESCE(r.ny, j.ny) AS ny,
       COALESCE(r.nz, j.nz) AS nz,
       r.status       AS result_status,
       r.dp_star      AS dp_star,
       r.iterations   AS iterations,
       r.wall_s       AS wall_s,
       r.cpu_s        AS cpu_s,
       r.peak_rss_mb  AS peak_rss_mb,
       COALESCE(r.reason, j.error) AS reason,
       u.u            AS u,
       u.rde          AS rde
FROM study_jobs sj
JOIN studies st ON st.id = sj.study_id
JOIN series se  ON se.id = sj.series_id
JOIN jobs j     ON j.id = sj.job_id
LEFT JOIN results r ON r.job_id = j.id
LEFT JOIN uncertainties u ON u.series_id = se.id AND u.job_id = j.id;
)sql";

// Step 2 — nominal Δ* and the per-series view (study conveniences): the
// Δ* a study requested for each grid (NULL for explicit cells) beside the
// actual one; uncertainties copy it from study_jobs on insert; v_series
// puts f0, the method and the finest grid's U and RDE in one row.
constexpr const char* kV2NominalDeltaStar = R"sql(
ALTER TABLE study_jobs ADD COLUMN delta_star_nominal REAL;
ALTER TABLE uncertainties ADD COLUMN delta_star_nominal REAL;
CREATE TRIGGER uncertainties_nominal AFTER INSERT ON uncertainties
BEGIN
  UPDATE uncertainties SET delta_star_nominal =
    (SELECT sj.delta_star_nominal FROM study_jobs sj WHERE sj.series_id = NEW.series_id AND sj.job_id = NEW.job_id)
  WHERE series_id = NEW.series_id AND job_id = NEW.job_id;
END;
DROP VIEW v_results;
CREATE VIEW v_results AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       sj.grid_index  AS grid_index,
       j.id           AS job_id,
       j.job_hash     AS job_hash,
       j.status       AS job_status,
       j.attempts     AS attempts,
       COALESCE(r.delta_star, j.delta_star) AS delta_star,
       sj.delta_star_nominal AS delta_star_nominal,
       COALESCE(r.nx, j.nx) AS nx,
       COALESCE(r.ny, j.ny) AS ny,
       COALESCE(r.nz, j.nz) AS nz,
       r.status       AS result_status,
       r.dp_star      AS dp_star,
       r.iterations   AS iterations,
       r.wall_s       AS wall_s,
       r.cpu_s        AS cpu_s,
       r.peak_rss_mb  AS peak_rss_mb,
       COALESCE(r.reason, j.error) AS reason,
       u.u            AS u,
       u.rde          AS rde
FROM study_jobs sj
JOIN studies st ON st.id = sj.study_id
JOIN series se  ON se.id = sj.series_id
JOIN jobs j     ON j.id = sj.job_id
LEFT JOIN results r ON r.job_id = j.id
LEFT JOIN uncertainties u ON u.series_id = se.id AND u.job_id = j.id;
;
CREATE VIEW v_series AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       se.status      AS series_status,
       -- verdict: add the series' verdict column here (e.g. se.verdict AS verdict)
       e.status       AS extrapolation_status,
       e.method       AS method,
       e.f0           AS f0,
       e.p            AS p,
       e.sigma_re     AS sigma_re,
       e.fs           AS fs,
       (SELECT COUNT(*) FROM uncertainties n WHERE n.series_id = se.id) AS ng,
       fu.delta_star  AS finest_delta_star,
       fu.delta_star_nominal AS finest_delta_star_nominal,
       fu.f           AS finest_dp_star,
       fu.u           AS finest_u,
       fu.rde         AS finest_rde
FROM series se
JOIN studies st ON st.id = se.study_id
LEFT JOIN extrapolations e ON e.series_id = se.id AND e.chosen = 1
LEFT JOIN uncertainties fu ON fu.series_id = se.id AND fu.delta_star =
  (SELECT MIN(m.delta_star) FROM uncertainties m WHERE m.series_id = se.id);
)sql";

// Slurm job state for `status` (feature: Slurm executor): the queue's word
// for a job (PENDING, RUNNING ...) and why it waits (Priority,
// JobArrayTaskLimit ...), as last polled; NULL for local jobs.
constexpr const char* kV3SlurmState = R"sql(
ALTER TABLE jobs ADD COLUMN queue_state TEXT;
ALTER TABLE jobs ADD COLUMN queue_reason TEXT;
)sql";

// Step 4 — series verdicts (docs/EXTRAPOLATION.md "Verdicts"): one word per
// series and its reasons as a JSON array of sentences, added to v_series.
constexpr const char* kV4SeriesVerdict = R"sql(
ALTER TABLE series ADD COLUMN verdict TEXT
  CHECK (verdict IS NULL OR verdict IN ('converged','pre-asymptotic','unreliable','insufficient_grids'));
ALTER TABLE series ADD COLUMN verdict_reasons TEXT;
DROP VIEW v_series;
CREATE VIEW v_series AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       se.status      AS series_status,
       se.verdict     AS verdict,
       se.verdict_reasons AS verdict_reasons,
       e.status       AS extrapolation_status,
       e.method       AS method,
       e.f0           AS f0,
       e.p            AS p,
       e.sigma_re     AS sigma_re,
       e.fs           AS fs,
       (SELECT COUNT(*) FROM uncertainties n WHERE n.series_id = se.id) AS ng,
       fu.delta_star  AS finest_delta_star,
       fu.delta_star_nominal AS finest_delta_star_nominal,
       fu.f           AS finest_dp_star,
       fu.u           AS finest_u,
       fu.rde         AS finest_rde
FROM series se
JOIN studies st ON st.id = se.study_id
LEFT JOIN extrapolations e ON e.series_id = se.id AND e.chosen = 1
LEFT JOIN uncertainties fu ON fu.series_id = se.id AND fu.delta_star =
  (SELECT MIN(m.delta_star) FROM uncertainties m WHERE m.series_id = se.id);
)sql";

// Step 7 — adaptive grid series (sched/adaptive_series.h): a series run to a
// target RDE is 'refining' until it stops, then 'target_met' or
// 'target_not_reached'; adaptive_note is the decision's sentence. NULL for
// series with a grid list.
constexpr const char* kV7AdaptiveSeries = R"sql(
ALTER TABLE series ADD COLUMN adaptive_status TEXT
  CHECK (adaptive_status IS NULL OR adaptive_status IN ('refining','target_met','target_not_reached'));
ALTER TABLE series ADD COLUMN adaptive_note TEXT;
)sql";

// Step 9 — indexes for the scheduler's per-job questions at ensemble scale
// (tens of thousands of jobs): is a series of the study still open
// (Store::refresh_study_status), and the first queued job of each grid
// size (sched/budget_claim.cpp).
constexpr const char* kV9ScaleIndexes = R"sql(
CREATE INDEX series_study_status ON series(study_id, status);
CREATE INDEX jobs_queue ON jobs(status, nx, ny, nz, id);
)sql";

// Step 10 — the coverage self-check of a finished series
// (extrap/self_check.h), made once when the series finishes, read by reports.
constexpr const char* kV10Coverage = R"sql(
ALTER TABLE series ADD COLUMN coverage_json TEXT;
)sql";

// Foreign keys off for the migration's transaction, on again afterwards
// (also when a step throws).
struct ForeignKeysOff {
  Database& db;
  explicit ForeignKeysOff(Database& d) : db(d) { db.exec("PRAGMA foreign_keys = OFF"); }
  ~ForeignKeysOff() {
    try {
      db.exec("PRAGMA foreign_keys = ON");
    } catch (...) {  // a destructor must not throw; the connection is unusable anyway then
    }
  }
  ForeignKeysOff(const ForeignKeysOff&) = delete;
  ForeignKeysOff& operator=(const ForeignKeysOff&) = delete;
};

}  // namespace

int schema_version(Database& db) {
  auto st = db.prepare("PRAGMA user_version");
  st.step();
  return static_cast<int>(st.as_int(0));
}

void migrate(Database& db, int target) {
  // Any number of processes may open a new file at once: the switch to WAL
  // is retried while another one holds the file (store/journal_mode.h), and
  // the version check and every step run in one exclusive transaction, so
  // one process creates the tables and the others, waiting on the busy
  // handler, find them made.
  enable_wal(db);
  db.exec("PRAGMA synchronous = NORMAL");
  // Step 5 rebuilds the series table: dropping it must not cascade to the
  // rows that reference it (the pragma is a no-op inside a transaction).
  ForeignKeysOff fk_off(db);  // declared first: restored after the transaction ends
  Transaction tx(db, Begin::kExclusive);
  const int v = schema_version(db);
  if (v > kSchemaVersion) throw InputError("--db", newer_schema_message(db, v, kSchemaVersion));
  if (v < 1 && target >= 1) db.exec(kV1);
  if (v < 2 && target >= 2) db.exec(kV2NominalDeltaStar);
  if (v < 3 && target >= 3) db.exec(kV3SlurmState);
  if (v < 4 && target >= 4) db.exec(kV4SeriesVerdict);
  if (v < 5 && target >= 5) migrate_series_transfer(db);  // transfer columns (schema_transfer.cpp)
  if (v < 6 && target >= 6) migrate_alignment(db);        // alignment check (schema_alignment.cpp)
  if (v < 7 && target >= 7) db.exec(kV7AdaptiveSeries);
  if (v < 8 && target >= 8) db.exec(kV8Ensembles);  // ensembles (store/schema_ensembles.h)
  if (v < 9 && target >= 9) db.exec(kV9ScaleIndexes);
  if (v < 10 && target >= 10) db.exec(kV10Coverage);
  if (v < 11 && target >= 11) migrate_job_hashes(db);  // defaults filled in (schema_job_hashes.cpp)
  if (v < 12 && target >= 12) migrate_series_quantity(db);  // external quantities (schema_quantity.cpp)
  if (v < 13 && target >= 13) migrate_series_levels(db);    // external factor levels (schema_levels.cpp)
  if ((v < 5 && target >= 5) || (v < 11 && target >= 11) || (v < 12 && target >= 12) || (v < 13 && target >= 13)) {
    auto fk = db.prepare("PRAGMA foreign_key_check");
    if (fk.step()) throw SqliteError("migration left a dangling reference in table " + fk.as_text(0), SQLITE_ERROR);
  }
  // Not a numbered step (store/stability_view.h): created if missing, on the full schema only.
  if (std::max(v, target) >= 10) ensure_stability_view(db);
  const int now = std::max(v, target);
  if (now > v)  // who wrote this version: an older gridfree meeting the file names it (database_file.h)
    db.prepare("INSERT INTO events(kind, message) VALUES ('schema', ?)")
        .bind_all("schema version " + std::to_string(now) + " by " + version_string() + ", from version " +
                  std::to_string(v))
        .run();
  db.exec("PRAGMA user_version = " + std::to_string(now));
  tx.commit();
}

}  // namespace gridfree
