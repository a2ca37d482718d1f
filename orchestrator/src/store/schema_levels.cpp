// SPDX-License-Identifier: GPL-3.0-or-later
// Step 13 — the factor levels of a series (docs/DATABASE.md "series",
// docs/EXTERNAL.md "Factors, designs and ensembles"): a series is its case,
// its factor levels and its quantity. An external case's factors are the
// study's own (template placeholders), kept as one canonical JSON text
// `levels` ({"scheme":"QUICK"}, keys in byte order; '{}' without factors)
// in the UNIQUE key; the particle bed's factor columns (convection,
// fwhm_dp, drag, deposition) become NULL for external series, which they
// never applied to. The table is rebuilt as in step 12 (ids kept; the
// caller runs this inside the migration's transaction with foreign keys
// off), and the views that read the key are made again:
//   v_results, v_series   + quantity, levels, value (the series' quantity:
//                          dp* or the external quantity)
//   v_ensemble_budget     one row per configuration now includes the
//                          quantity and levels; NULL-safe joins (IS)
#include "store/schema_steps.h"

namespace gridfree {
namespace {

constexpr const char* kRebuildWithLevels = R"sql(
CREATE TABLE series_before_v13 AS SELECT * FROM series;
DROP TABLE series;
CREATE TABLE series(
  id         INTEGER PRIMARY KEY,
  study_id   INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  position   INTEGER NOT NULL,
  case_name  TEXT NOT NULL,
  convection TEXT,
  fwhm_dp    REAL,
  drag       TEXT,
  deposition TEXT DEFAULT 'diffusion',
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
  levels         TEXT NOT NULL DEFAULT '{}',
  UNIQUE (study_id, case_name, convection, fwhm_dp, drag, deposition,
          pre_deposition, sampling, integration, diffusivity, steps, quantity, levels)
);
INSERT INTO series(id, study_id, position, case_name, convection, fwhm_dp, drag, deposition, status,
                   verdict, verdict_reasons, pre_deposition, sampling, integration, diffusivity, steps,
                   adaptive_status, adaptive_note, coverage_json, quantity, levels)
SELECT id, study_id, position, case_name,
       CASE WHEN quantity = '' THEN convection END, CASE WHEN quantity = '' THEN fwhm_dp END,
       CASE WHEN quantity = '' THEN drag END, CASE WHEN quantity = '' THEN deposition END, status,
       verdict, verdict_reasons, pre_deposition, sampling, integration, diffusivity, steps,
       adaptive_status, adaptive_note, coverage_json, quantity, '{}' FROM series_before_v13;
DROP TABLE series_before_v13;
CREATE INDEX series_study_status ON series(study_id, status);
-- NULLs are distinct in a UNIQUE key: an external series' own key.
CREATE UNIQUE INDEX series_external_key ON series(study_id, case_name, quantity, levels) WHERE quantity <> '';
DROP VIEW IF EXISTS v_results;
CREATE VIEW v_results AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       se.quantity    AS quantity,
       se.levels      AS levels,
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
       CASE WHEN se.quantity = '' THEN r.dp_star END AS dp_star,
       CASE WHEN se.quantity = '' THEN r.dp_star
            WHEN json_valid(r.result_json) THEN json_extract(r.result_json, '$.quantities.' || se.quantity) END AS value,
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
DROP VIEW IF EXISTS v_series;
CREATE VIEW v_series AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       se.quantity    AS quantity,
       se.levels      AS levels,
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
DROP VIEW IF EXISTS v_ensemble_budget;
CREATE VIEW v_ensemble_budget AS
WITH inst AS (
  SELECT en.study_id, en.name AS ensemble, se.id AS series_id, se.convection, se.fwhm_dp, se.drag,
         se.deposition, se.quantity, se.levels, se.verdict, e.f0
  FROM ensembles en
  JOIN series se ON se.study_id = en.study_id AND se.case_name = en.case_name
  LEFT JOIN extrapolations e ON e.series_id = se.id AND e.chosen = 1
),
cfg AS (
  SELECT study_id, ensemble, convection, fwhm_dp, drag, deposition, quantity, levels,
         COUNT(*) AS instances,
         SUM(CASE WHEN verdict = 'converged' THEN 1 ELSE 0 END) AS instances_converged,
         COUNT(f0) AS n_f0, AVG(f0) AS f0_mean, MIN(f0) AS f0_min, MAX(f0) AS f0_max
  FROM inst GROUP BY study_id, ensemble, convection, fwhm_dp, drag, deposition, quantity, levels
),
cfg_sd AS (
  SELECT c.*,
         CASE WHEN c.n_f0 >= 2 THEN
           sqrt(SUM((i.f0 - c.f0_mean) * (i.f0 - c.f0_mean)) / (c.n_f0 - 1)) END AS f0_sd
  FROM cfg c
  JOIN inst i ON i.study_id = c.study_id AND i.ensemble = c.ensemble AND i.convection IS c.convection
             AND i.fwhm_dp IS c.fwhm_dp AND i.drag IS c.drag AND i.deposition IS c.deposition
             AND i.quantity = c.quantity AND i.levels = c.levels
  GROUP BY c.study_id, c.ensemble, c.convection, c.fwhm_dp, c.drag, c.deposition, c.quantity, c.levels
),
pts AS (
  SELECT i.study_id, i.ensemble, i.convection, i.fwhm_dp, i.drag, i.deposition, i.quantity, i.levels,
         sj.grid_index, sj.delta_star_nominal, u.delta_star, u.u, u.rde
  FROM inst i
  JOIN study_jobs sj ON sj.series_id = i.series_id
  LEFT JOIN uncertainties u ON u.series_id = i.series_id AND u.job_id = sj.job_id
),
grid AS (
  SELECT study_id, ensemble, convection, fwhm_dp, drag, deposition, quantity, levels, grid_index,
         MAX(delta_star_nominal) AS delta_star_nominal, AVG(delta_star) AS delta_star,
         COUNT(rde) AS n_rde, AVG(u) AS u_mean, AVG(rde) AS rde_mean, MIN(rde) AS rde_min, MAX(rde) AS rde_max
  FROM pts GROUP BY study_id, ensemble, convection, fwhm_dp, drag, deposition, quantity, levels, grid_index
),
grid_sd AS (
  SELECT g.*,
         CASE WHEN g.n_rde >= 2 THEN
           sqrt(SUM((p.rde - g.rde_mean) * (p.rde - g.rde_mean)) / (g.n_rde - 1)) END AS rde_sd
  FROM grid g
  JOIN pts p ON p.study_id = g.study_id AND p.ensemble = g.ensemble AND p.convection IS g.convection
            AND p.fwhm_dp IS g.fwhm_dp AND p.drag IS g.drag AND p.deposition IS g.deposition
            AND p.quantity = g.quantity AND p.levels = g.levels AND p.grid_index = g.grid_index
  GROUP BY g.study_id, g.ensemble, g.convection, g.fwhm_dp, g.drag, g.deposition, g.quantity, g.levels, g.grid_index
)
SELECT st.name AS study, c.ensemble AS ensemble,
       c.convection AS convection, c.fwhm_dp AS fwhm_dp, c.drag AS drag, c.deposition AS deposition,
       c.quantity AS quantity, c.levels AS levels,
       c.instances AS instances, c.instances_converged AS instances_converged, c.n_f0 AS instances_with_f0,
       c.f0_mean AS f0_mean, c.f0_sd AS f0_sd, c.f0_min AS f0_min, c.f0_max AS f0_max,
       c.f0_sd / sqrt(c.n_f0) AS f0_sem,
       CASE WHEN c.f0_mean <> 0 THEN c.f0_sd / abs(c.f0_mean) END AS f0_spread_rel,
       g.grid_index AS grid_index, g.delta_star_nominal AS delta_star_nominal, g.delta_star AS delta_star,
       g.n_rde AS instances_with_u, g.u_mean AS u_mean,
       g.rde_mean AS rde_mean, g.rde_sd AS rde_sd, g.rde_min AS rde_min, g.rde_max AS rde_max
FROM cfg_sd c
JOIN studies st ON st.id = c.study_id
JOIN grid_sd g ON g.study_id = c.study_id AND g.ensemble = c.ensemble AND g.convection IS c.convection
              AND g.fwhm_dp IS c.fwhm_dp AND g.drag IS c.drag AND g.deposition IS c.deposition
              AND g.quantity = c.quantity AND g.levels = c.levels;
)sql";

}  // namespace

void migrate_series_levels(Database& db) { db.exec(kRebuildWithLevels); }

}  // namespace gridfree
