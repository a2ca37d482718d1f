// SPDX-License-Identifier: GPL-3.0-or-later
// Store: series, extrapolations, study status and summaries.
#include "store/store.h"

namespace gridfree {
namespace {

SeriesInfo read_series(const Statement& st) {
  SeriesInfo s;
  s.id = st.as_int(0);
  s.study_id = st.as_int(1);
  s.key.case_name = st.as_text(2);
  s.key.convection = st.as_text(3);
  s.key.fwhm_dp = st.as_double(4);
  s.key.drag = st.as_text(5);
  s.key.deposition = st.as_text(6);
  s.status = st.as_text(7);
  s.verdict = st.as_text(8);
  s.verdict_reasons = st.as_text(9);
  s.coverage_json = st.as_text(10);
  s.key.quantity = st.as_text(11);
  s.key.levels = levels_from_json(st.as_text(12));
  return s;
}

// An external series' convection, fwhm_dp, drag, deposition are NULL (read as "" and 0).
constexpr const char* kSeriesColumns =
    "SELECT id, study_id, case_name, COALESCE(convection, ''), COALESCE(fwhm_dp, 0), COALESCE(drag, ''), "
    "COALESCE(deposition, ''), status, COALESCE(verdict, ''), "
    "COALESCE(verdict_reasons, ''), COALESCE(coverage_json, ''), quantity, levels FROM series ";

}  // namespace

void Store::store_coverage(long long series_id, const std::string& json) {
  db_.prepare("UPDATE series SET coverage_json = ? WHERE id = ?").bind_all(json, series_id).run();
}

std::vector<SeriesInfo> Store::series_of_study(long long study_id) {
  std::vector<SeriesInfo> out;
  auto st = db_.prepare(std::string(kSeriesColumns) + "WHERE study_id = ? ORDER BY position");
  st.bind_all(study_id);
  while (st.step()) out.push_back(read_series(st));
  return out;
}

std::vector<SeriesInfo> Store::series_ready(long long study_id) {
  std::vector<SeriesInfo> out;
  auto st = db_.prepare(std::string(kSeriesColumns) +
                        "WHERE study_id = ? AND status IN ('queued','running') AND NOT EXISTS ("
                        " SELECT 1 FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id"
                        " WHERE sj.series_id = series.id AND sj.alignment_only = 0 AND j.status IN ('queued','running')) "
                        "ORDER BY position");
  st.bind_all(study_id);
  while (st.step()) out.push_back(read_series(st));
  return out;
}

std::vector<SeriesInfo> Store::series_ready_of_job(long long study_id, long long job_id) {
  // "+study_id": look the job's rows up by job_id (study_jobs_job), not by
  // study, which would read every row of the study.
  std::vector<SeriesInfo> out;
  auto st = db_.prepare(std::string(kSeriesColumns) +
                        "WHERE id IN (SELECT series_id FROM study_jobs WHERE job_id = ?2 AND +study_id = ?1) "
                        "AND status IN ('queued','running') AND NOT EXISTS ("
                        " SELECT 1 FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id"
                        " WHERE sj.series_id = series.id AND sj.alignment_only = 0 AND j.status IN ('queued','running')) "
                        "ORDER BY position");
  st.bind_all(study_id, job_id);
  while (st.step()) out.push_back(read_series(st));
  return out;
}

std::vector<SeriesPoint> Store::series_points(long long series_id) {
  std::vector<SeriesPoint> out;
  auto st = db_.prepare(
      "SELECT j.id, j.job_hash, j.status, COALESCE(r.status, ''), COALESCE(r.reason, j.error, ''), "
      "COALESCE(r.delta_star, j.delta_star), j.nx, j.ny, j.nz, "
      // An external series reads its quantity from the result (docs/EXTERNAL.md).
      "CASE WHEN se.quantity = '' THEN r.dp_star WHEN json_valid(r.result_json) THEN "
      " json_extract(r.result_json, '$.quantities.' || se.quantity) END, COALESCE(r.iterations, 0), "
      "COALESCE(r.wall_s, 0), COALESCE(r.cpu_s, 0), COALESCE(r.peak_rss_mb, 0), "
      "COALESCE(CASE WHEN json_valid(r.result_json) THEN json_extract(r.result_json, '$.outcome') END, ''), "
      "COALESCE(CASE WHEN json_valid(r.result_json) THEN "
      " json_extract(r.result_json, '$.extra.correction_relaxed_from_iteration') END, 0) "
      "FROM study_jobs sj JOIN series se ON se.id = sj.series_id JOIN jobs j ON j.id = sj.job_id "
      "LEFT JOIN results r ON r.job_id = j.id "
      "WHERE sj.series_id = ? AND sj.alignment_only = 0 ORDER BY sj.grid_index");
  st.bind_all(series_id);
  while (st.step()) {
    SeriesPoint p;
    p.job_id = st.as_int(0);
    p.job_hash = st.as_text(1);
    p.job_status = st.as_text(2);
    p.result_status = st.as_text(3);
    p.reason = st.as_text(4);
    p.delta_star = st.as_double(5);
    p.cells = {static_cast<int>(st.as_int(6)), static_cast<int>(st.as_int(7)), static_cast<int>(st.as_int(8))};
    p.dp_star = st.as_opt_double(9);
    p.iterations = static_cast<int>(st.as_int(10));
    p.wall_s = st.as_double(11);
    p.cpu_s = st.as_double(12);
    p.peak_rss_mb = st.as_double(13);
    p.worker_outcome = st.as_text(14);
    p.remedy_from_iteration = static_cast<int>(st.as_int(15));
    out.push_back(std::move(p));
  }
  return out;
}

void Store::store_extrapolation(long long series_id, const std::vector<ExtrapolationRow>& fits,
                                const std::vector<UncertaintyRow>& uncertainties,
                                const std::optional<VerdictRow>& verdict) {
  Transaction tx(db_);
  db_.prepare("DELETE FROM extrapolations WHERE series_id = ?").bind_all(series_id).run();
  db_.prepare("DELETE FROM uncertainties WHERE series_id = ?").bind_all(series_id).run();
  auto ins = db_.prepare(
      "INSERT INTO extrapolations(series_id, method, f0, p, c, c1, c2, sigma_re, data_range, fs, chosen, "
      "status, detail_json) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?)");
  for (const auto& f : fits) {
    ins.reset();
    ins.bind_all(series_id, f.method, f.f0, f.p, f.c, f.c1, f.c2, f.sigma_re, f.data_range, f.fs,
                 f.chosen ? 1 : 0, f.status, f.detail_json)
        .run();
  }
  auto unc = db_.prepare(
      "INSERT INTO uncertainties(series_id, job_id, delta_star, f, u, rde) VALUES (?,?,?,?,?,?)");
  for (const auto& u : uncertainties) {
    unc.reset();
    unc.bind_all(series_id, u.job_id, u.delta_star, u.f, u.u, u.rde).run();
  }
  db_.prepare("UPDATE series SET status = 'done' WHERE id = ?").bind_all(series_id).run();
  if (verdict)
    db_.prepare("UPDATE series SET verdict = ?, verdict_reasons = ? WHERE id = ?")
        .bind_all(verdict->value, verdict->reasons_json, series_id)
        .run();
  tx.commit();
}

std::vector<ExtrapolationRow> Store::extrapolations(long long series_id) {
  std::vector<ExtrapolationRow> out;
  auto st = db_.prepare(
      "SELECT method, f0, p, c, c1, c2, sigma_re, data_range, fs, chosen, COALESCE(status, ''), "
      "COALESCE(detail_json, '') FROM extrapolations WHERE series_id = ? ORDER BY method DESC");
  st.bind_all(series_id);
  while (st.step()) {
    ExtrapolationRow r;
    r.method = st.as_text(0);
    r.f0 = st.as_opt_double(1);
    r.p = st.as_opt_double(2);
    r.c = st.as_opt_double(3);
    r.c1 = st.as_opt_double(4);
    r.c2 = st.as_opt_double(5);
    r.sigma_re = st.as_opt_double(6);
    r.data_range = st.as_opt_double(7);
    r.fs = st.as_opt_double(8);
    r.chosen = st.as_int(9) != 0;
    r.status = st.as_text(10);
    r.detail_json = st.as_text(11);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<UncertaintyRow> Store::uncertainties(long long series_id) {
  std::vector<UncertaintyRow> out;
  auto st = db_.prepare(
      "SELECT job_id, delta_star, f, u, rde FROM uncertainties WHERE series_id = ? ORDER BY delta_star");
  st.bind_all(series_id);
  while (st.step())
    out.push_back({st.as_int(0), st.as_double(1), st.as_opt_double(2), st.as_opt_double(3), st.as_opt_double(4)});
  return out;
}

// While a series is open the answer needs two index probes (schema step 9's
// series(study_id, status); study_jobs by study, whose first rows are the
// first claimed), not a count of the study's jobs: the scheduler asks after
// every job. Only when no series is open are the jobs counted (once, at the
// study's end).
std::string Store::refresh_study_status(long long study_id) {
  Transaction tx(db_);
  auto open = db_.prepare(
      "SELECT s.status, "
      " EXISTS (SELECT 1 FROM series WHERE study_id = s.id AND status IN ('queued','running','failed')), "
      " EXISTS (SELECT 1 FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
      "   WHERE sj.study_id = s.id AND j.status <> 'queued') "
      "FROM studies s WHERE s.id = ?");
  open.bind_all(study_id);
  if (!open.step()) return "";
  const std::string status = open.as_text(0);
  if (status == "cancelled") return status;
  std::string next;
  if (open.as_int(1) != 0) {
    next = open.as_int(2) != 0 ? "running" : "queued";
  } else {
    auto st = db_.prepare(
        "SELECT "
        " (SELECT COUNT(*) FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
        "   WHERE sj.study_id = ?1 AND j.status IN ('queued','running')), "
        " (SELECT COUNT(*) FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
        "   WHERE sj.study_id = ?1 AND j.status <> 'done'), "
        " (SELECT COUNT(*) FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
        "   WHERE sj.study_id = ?1 AND j.status <> 'queued')");
    st.bind_all(study_id);
    st.step();
    const long long open_jobs = st.as_int(0), not_done = st.as_int(1), started = st.as_int(2);
    if (open_jobs == 0)
      next = not_done == 0 ? "done" : "failed";
    else
      next = started > 0 ? "running" : "queued";
  }
  if (next != status) {
    const bool final_state = next == "done" || next == "failed";
    db_.prepare(final_state ? "UPDATE studies SET status = ?, finished_at = strftime('%Y-%m-%dT%H:%M:%fZ','now') WHERE id = ?"
                            : "UPDATE studies SET status = ?, finished_at = NULL WHERE id = ?")
        .bind_all(next, study_id).run();
  }
  tx.commit();
  return next;
}

std::vector<StudyStatus> Store::statuses(std::optional<long long> study) {
  std::vector<StudyStatus> out;
  auto st = db_.prepare(
      "SELECT s.id, s.name, s.status, s.submitted_at, COALESCE(s.finished_at, ''), COALESCE(s.design, ''), "
      " COUNT(j.id), "
      " SUM(j.status = 'queued'), SUM(j.status = 'running'), SUM(j.status = 'done'), "
      " SUM(j.status = 'failed'), SUM(j.status = 'cancelled'), SUM(r.status = 'converged'), "
      " AVG(r.wall_s), "
      " (SELECT COUNT(*) FROM series WHERE study_id = s.id), "
      " (SELECT COUNT(*) FROM series WHERE study_id = s.id AND status = 'done') "
      "FROM studies s LEFT JOIN (SELECT DISTINCT study_id, job_id FROM study_jobs) sj ON sj.study_id = s.id "
      "LEFT JOIN jobs j ON j.id = sj.job_id LEFT JOIN results r ON r.job_id = j.id "
      "WHERE (?1 IS NULL OR s.id = ?1) GROUP BY s.id ORDER BY s.id");
  st.bind_all(study ? std::optional<long long>(*study) : std::optional<long long>());
  while (st.step()) {
    StudyStatus s;
    s.id = st.as_int(0);
    s.name = st.as_text(1);
    s.status = st.as_text(2);
    s.submitted_at = st.as_text(3);
    s.finished_at = st.as_text(4);
    s.design = st.as_text(5);
    s.jobs = static_cast<int>(st.as_int(6));
    s.queued = static_cast<int>(st.as_int(7));
    s.running = static_cast<int>(st.as_int(8));
    s.done = static_cast<int>(st.as_int(9));
    s.failed = static_cast<int>(st.as_int(10));
    s.cancelled = static_cast<int>(st.as_int(11));
    s.converged = static_cast<int>(st.as_int(12));
    s.mean_wall_s = st.as_double(13);
    s.series = static_cast<int>(st.as_int(14));
    s.series_done = static_cast<int>(st.as_int(15));
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace gridfree
