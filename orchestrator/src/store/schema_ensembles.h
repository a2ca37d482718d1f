// SPDX-License-Identifier: GPL-3.0-or-later
// Schema step 8 — ensembles (feature: ensembles of frozen instances,
// docs/DATABASE.md "ensembles", docs/EXTRAPOLATION.md "Ensembles").
//
// ensembles: which cases of a study are instances of one physical state.
// v_ensemble_budget: one row per (study, ensemble, configuration, grid):
// the ensemble statistics of f0 (over the instances that have an f0,
// whatever their verdict; the converged ones are counted) and of U and RDE
// at that grid (over the instances with a value there).
//
//   mean  x̄ = Σ x_i / n      sample sd  s = sqrt(Σ (x_i − x̄)² / (n − 1))  (n ≥ 2)
//   standard error of the mean  s / sqrt(n)      relative spread  s / |x̄|
//
// sqrt() is SQLite's math function (SQLite ≥ 3.35 built with
// SQLITE_ENABLE_MATH_FUNCTIONS, as Debian's is).
#pragma once

namespace gridfree {

inline constexpr const char* kV8Ensembles = R"sql(
CREATE TABLE ensembles(
  study_id  INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  name      TEXT NOT NULL,
  case_name TEXT NOT NULL,
  PRIMARY KEY (study_id, case_name)
);
CREATE VIEW v_ensemble_budget AS
WITH inst AS (
  SELECT en.study_id, en.name AS ensemble, se.id AS series_id, se.convection, se.fwhm_dp, se.drag,
         se.deposition, se.verdict, e.f0
  FROM ensembles en
  JOIN series se ON se.study_id = en.study_id AND se.case_name = en.case_name
  LEFT JOIN extrapolations e ON e.series_id = se.id AND e.chosen = 1
),
cfg AS (
  SELECT study_id, ensemble, convection, fwhm_dp, drag, deposition,
         COUNT(*) AS instances,
         SUM(CASE WHEN verdict = 'converged' THEN 1 ELSE 0 END) AS instances_converged,
         COUNT(f0) AS n_f0, AVG(f0) AS f0_mean, MIN(f0) AS f0_min, MAX(f0) AS f0_max
  FROM inst GROUP BY study_id, ensemble, convection, fwhm_dp, drag, deposition
),
cfg_sd AS (
  SELECT c.*,
         CASE WHEN c.n_f0 >= 2 THEN
           sqrt(SUM((i.f0 - c.f0_mean) * (i.f0 - c.f0_mean)) / (c.n_f0 - 1)) END AS f0_sd
  FROM cfg c
  JOIN inst i ON i.study_id = c.study_id AND i.ensemble = c.ensemble AND i.convection = c.convection
             AND i.fwhm_dp = c.fwhm_dp AND i.drag = c.drag AND i.deposition = c.deposition
  GROUP BY c.study_id, c.ensemble, c.convection, c.fwhm_dp, c.drag, c.deposition
),
pts AS (
  SELECT i.study_id, i.ensemble, i.convection, i.fwhm_dp, i.drag, i.deposition, sj.grid_index,
         sj.delta_star_nominal, u.delta_star, u.u, u.rde
  FROM inst i
  JOIN study_jobs sj ON sj.series_id = i.series_id
  LEFT JOIN uncertainties u ON u.series_id = i.series_id AND u.job_id = sj.job_id
),
grid AS (
  SELECT study_id, ensemble, convection, fwhm_dp, drag, deposition, grid_index,
         MAX(delta_star_nominal) AS delta_star_nominal, AVG(delta_star) AS delta_star,
         COUNT(rde) AS n_rde, AVG(u) AS u_mean, AVG(rde) AS rde_mean, MIN(rde) AS rde_min, MAX(rde) AS rde_max
  FROM pts GROUP BY study_id, ensemble, convection, fwhm_dp, drag, deposition, grid_index
),
grid_sd AS (
  SELECT g.*,
         CASE WHEN g.n_rde >= 2 THEN
           sqrt(SUM((p.rde - g.rde_mean) * (p.rde - g.rde_mean)) / (g.n_rde - 1)) END AS rde_sd
  FROM grid g
  JOIN pts p ON p.study_id = g.study_id AND p.ensemble = g.ensemble AND p.convection = g.convection
            AND p.fwhm_dp = g.fwhm_dp AND p.drag = g.drag AND p.deposition = g.deposition
            AND p.grid_index = g.grid_index
  GROUP BY g.study_id, g.ensemble, g.convection, g.fwhm_dp, g.drag, g.deposition, g.grid_index
)
SELECT st.name AS study, c.ensemble AS ensemble,
       c.convection AS convection, c.fwhm_dp AS fwhm_dp, c.drag AS drag, c.deposition AS deposition,
       c.instances AS instances, c.instances_converged AS instances_converged, c.n_f0 AS instances_with_f0,
       c.f0_mean AS f0_mean, c.f0_sd AS f0_sd, c.f0_min AS f0_min, c.f0_max AS f0_max,
       c.f0_sd / sqrt(c.n_f0) AS f0_sem,
       CASE WHEN c.f0_mean <> 0 THEN c.f0_sd / abs(c.f0_mean) END AS f0_spread_rel,
       g.grid_index AS grid_index, g.delta_star_nominal AS delta_star_nominal, g.delta_star AS delta_star,
       g.n_rde AS instances_with_u, g.u_mean AS u_mean,
       g.rde_mean AS rde_mean, g.rde_sd AS rde_sd, g.rde_min AS rde_min, g.rde_max AS rde_max
FROM cfg_sd c
JOIN studies st ON st.id = c.study_id
JOIN grid_sd g ON g.study_id = c.study_id AND g.ensemble = c.ensemble AND g.convection = c.convection
              AND g.fwhm_dp = c.fwhm_dp AND g.drag = c.drag AND g.deposition = c.deposition;
)sql";

}  // namespace gridfree
