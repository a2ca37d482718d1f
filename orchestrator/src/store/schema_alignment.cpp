// SPDX-License-Identifier: GPL-3.0-or-later
// Step 6 — the alignment check of a study (feature: alignment check as a
// study option, docs/DATABASE.md, docs/TRANSFER.md "Alignment check").
//
// alignment_jobs links each variant job (the base grid's cells changed by
// dnx, dny, dnz) to its series, the grid it re-aligns (grid_index) and that
// grid's own job (base_job_id); the base job itself is a row with offsets
// 0, 0, 0, so the variants of a grid are all its rows. A variant is an
// ordinary job linked to the study in study_jobs with alignment_only = 1
// (queued, cached, retried like any job; not part of the series'
// extrapolation). v_alignment gives per series and grid
//
//   spread = (max dp* − min dp*) / mean dp*  over the grid's rows,
//
// only when every row converged with a dp* (and there are at least two),
// beside the base grid's U and f from the series' extrapolation.
#include "store/schema_steps.h"

namespace gridfree {
namespace {

constexpr const char* kV6Alignment = R"sql(
ALTER TABLE study_jobs ADD COLUMN alignment_only INTEGER NOT NULL DEFAULT 0;
CREATE TABLE alignment_jobs(
  series_id   INTEGER NOT NULL REFERENCES series(id) ON DELETE CASCADE,
  grid_index  INTEGER NOT NULL,
  job_id      INTEGER NOT NULL REFERENCES jobs(id),
  base_job_id INTEGER NOT NULL REFERENCES jobs(id),
  dnx INTEGER NOT NULL, dny INTEGER NOT NULL, dnz INTEGER NOT NULL,
  PRIMARY KEY (series_id, grid_index, job_id)
);
CREATE INDEX alignment_jobs_job ON alignment_jobs(job_id);
CREATE VIEW v_alignment AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       a.grid_index   AS grid_index,
       bj.nx AS nx, bj.ny AS ny, bj.nz AS nz,
       COALESCE(br.delta_star, bj.delta_star) AS delta_star,
       COUNT(*)       AS variants,
       COALESCE(SUM(r.status = 'converged' AND r.dp_star IS NOT NULL), 0) AS converged,
       MIN(r.dp_star) AS dp_star_min,
       MAX(r.dp_star) AS dp_star_max,
       AVG(r.dp_star) AS dp_star_mean,
       CASE WHEN COUNT(*) >= 2 AND COALESCE(SUM(r.status = 'converged' AND r.dp_star IS NOT NULL), 0) = COUNT(*)
            THEN (MAX(r.dp_star) - MIN(r.dp_star)) / AVG(r.dp_star) END AS spread,
       u.f            AS f,
       u.u            AS u,
       u.rde          AS rde
FROM alignment_jobs a
JOIN series se  ON se.id = a.series_id
JOIN studies st ON st.id = se.study_id
JOIN jobs bj    ON bj.id = a.base_job_id
LEFT JOIN results br ON br.job_id = a.base_job_id
LEFT JOIN results r  ON r.job_id = a.job_id
LEFT JOIN uncertainties u ON u.series_id = a.series_id AND u.job_id = a.base_job_id
GROUP BY a.series_id, a.grid_index;
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
LEFT JOIN uncertainties u ON u.series_id = se.id AND u.job_id = j.id
WHERE sj.alignment_only = 0;
)sql";

}  // namespace

void migrate_alignment(Database& db) { db.exec(kV6Alignment); }

}  // namespace gridfree
