// SPDX-License-Identifier: GPL-3.0-or-later
// v_stability (stability_view.h).
#include "store/stability_view.h"

namespace gridfree {
namespace {

// The worker's `outcome` (docs/INTERFACE.md §2) splits not_converged; results
// written before it existed are split by their reason. A job failed by the
// orchestrator after its timeouts has a reason starting "timed out".
constexpr const char* kStabilityView = R"sql(
CREATE VIEW IF NOT EXISTS v_stability AS
SELECT st.name        AS study,
       se.id          AS series_id,
       se.case_name   AS case_name,
       se.convection  AS convection,
       se.fwhm_dp     AS fwhm_dp,
       se.drag        AS drag,
       se.deposition  AS deposition,
       sj.grid_index  AS grid_index,
       sj.delta_star_nominal AS delta_star_nominal,
       COALESCE(r.delta_star, j.delta_star) AS delta_star,
       j.id           AS job_id,
       CASE
         WHEN r.status IS NULL THEN CASE WHEN j.status = 'cancelled' THEN 'cancelled'
                                         WHEN j.status = 'failed' AND substr(COALESCE(j.error, ''), 1, 9) = 'timed out'
                                           THEN 'timed_out'
                                         WHEN j.status = 'failed' THEN 'failed'
                                         ELSE 'pending' END
         WHEN r.status = 'not_converged' THEN
           CASE WHEN json_valid(r.result_json) AND json_extract(r.result_json, '$.outcome') IN ('stalled', 'iteration_cap')
                THEN json_extract(r.result_json, '$.outcome')
                WHEN instr(COALESCE(r.reason, ''), 'stalling for') > 0 THEN 'stalled'
                ELSE 'iteration_cap' END
         WHEN r.status = 'failed' AND substr(COALESCE(r.reason, ''), 1, 9) = 'timed out' THEN 'timed_out'
         ELSE r.status
       END            AS outcome,
       r.iterations   AS iterations,
       r.dp_star      AS dp_star,
       COALESCE(r.reason, j.error) AS reason
FROM study_jobs sj
JOIN studies st ON st.id = sj.study_id
JOIN series se  ON se.id = sj.series_id
JOIN jobs j     ON j.id = sj.job_id
LEFT JOIN results r ON r.job_id = j.id
WHERE sj.alignment_only = 0;
)sql";

}  // namespace

void ensure_stability_view(Database& db) { db.exec(kStabilityView); }

}  // namespace gridfree
