// SPDX-License-Identifier: GPL-3.0-or-later
// Store: the job state machine (claim, record, retry, release, stale requeue).
#include "store/store.h"

namespace gridfree {
namespace {

constexpr const char* kNow = "strftime('%Y-%m-%dT%H:%M:%fZ','now')";

bool owned_running(Database& db, long long job_id, const std::string& owner, int* attempts) {
  auto st = db.prepare("SELECT attempts FROM jobs WHERE id = ? AND status = 'running' AND owner = ?");
  st.bind_all(job_id, owner);
  if (!st.step()) return false;
  if (attempts != nullptr) *attempts = static_cast<int>(st.as_int(0));
  return true;
}

void insert_result(Database& db, long long job_id, const ResultRow& r) {
  db.prepare(
        "INSERT INTO results(job_id, status, dp_star, delta_star, nx, ny, nz, iterations, wall_s, cpu_s, "
        "peak_rss_mb, result_json, reason) VALUES (?,?,?,NULLIF(?,0),NULLIF(?,0),NULLIF(?,0),NULLIF(?,0),?,?,?,?,?,?) "
        "ON CONFLICT(job_id) DO UPDATE SET status = excluded.status, dp_star = excluded.dp_star, "
        "delta_star = excluded.delta_star, nx = excluded.nx, ny = excluded.ny, nz = excluded.nz, "
        "iterations = excluded.iterations, wall_s = excluded.wall_s, cpu_s = excluded.cpu_s, "
        "peak_rss_mb = excluded.peak_rss_mb, result_json = excluded.result_json, reason = excluded.reason, "
        "recorded_at = excluded.recorded_at")
      .bind_all(job_id, r.status, r.dp_star, r.delta_star, r.cells[0], r.cells[1], r.cells[2], r.iterations,
                r.wall_s, r.cpu_s, r.peak_rss_mb,
                r.result_json.empty() ? std::optional<std::string>() : std::optional<std::string>(r.result_json),
                r.reason)
      .run();
}

void finish_job(Database& db, long long job_id, const ResultRow& r) {
  insert_result(db, job_id, r);
  const std::string status = r.status == "converged" ? "done" : "failed";
  db.prepare(std::string("UPDATE jobs SET status = ?, finished_at = ") + kNow +
             ", owner = NULL, error = ? WHERE id = ?")
      .bind_all(status,
                r.status == "converged" ? std::optional<std::string>()
                                        : std::optional<std::string>(r.status + ": " + r.reason),
                job_id)
      .run();
  db.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'result', ?)")
      .bind_all(job_id, r.status + (r.reason.empty() ? "" : ": " + r.reason)).run();
}

}  // namespace

std::vector<long long> Store::active_studies() {
  std::vector<long long> out;
  auto st = db_.prepare("SELECT id FROM studies WHERE status IN ('queued','running') ORDER BY id");
  while (st.step()) out.push_back(st.as_int(0));
  return out;
}

std::optional<ClaimedJob> Store::claim_next(std::optional<long long> study, const std::string& owner,
                                            std::optional<long long> only_job) {
  Transaction tx(db_);
  // With the job named, a lookup by its id (an "?2 IS NULL OR" would make
  // SQLite read the whole queue to find it).
  const std::string columns =
      "SELECT j.id, sj.study_id, j.job_hash, j.spec_json, j.attempts, j.nx, j.ny, j.nz "
      "FROM jobs j JOIN study_jobs sj ON sj.job_id = j.id "
      "JOIN studies s ON s.id = sj.study_id JOIN series se ON se.id = sj.series_id "
      "WHERE j.status = 'queued' AND s.status IN ('queued','running') AND (?1 IS NULL OR s.id = ?1) ";
  auto st = db_.prepare(columns + (only_job ? "AND j.id = ?2 " : "AND ?2 IS NULL ") +
                        "ORDER BY s.id, se.position, j.cells DESC, j.id LIMIT 1");
  st.bind_all(study ? std::optional<long long>(*study) : std::optional<long long>(), only_job);
  if (!st.step()) return std::nullopt;
  ClaimedJob job;
  job.job_id = st.as_int(0);
  job.study_id = st.as_int(1);
  job.job_hash = st.as_text(2);
  job.spec = nlohmann::json::parse(st.as_text(3));
  job.attempts = static_cast<int>(st.as_int(4)) + 1;
  job.cells = {static_cast<int>(st.as_int(5)), static_cast<int>(st.as_int(6)), static_cast<int>(st.as_int(7))};
  db_.prepare(std::string("UPDATE jobs SET status = 'running', attempts = attempts + 1, owner = ?, started_at = ") +
              kNow + ", finished_at = NULL WHERE id = ? AND status = 'queued'")
      .bind_all(owner, job.job_id).run();
  if (db_.changes() != 1) return std::nullopt;  // cannot happen under BEGIN IMMEDIATE
  db_.prepare("UPDATE studies SET status = 'running' WHERE id = ? AND status = 'queued'").bind_all(job.study_id).run();
  db_.prepare(
         "UPDATE series SET status = 'running' WHERE status = 'queued' AND id IN "
         "(SELECT series_id FROM study_jobs WHERE job_id = ?)")
      .bind_all(job.job_id).run();
  tx.commit();
  return job;
}

bool Store::record_result(long long job_id, const std::string& owner, const ResultRow& r) {
  Transaction tx(db_);
  if (!owned_running(db_, job_id, owner, nullptr)) return false;
  finish_job(db_, job_id, r);
  tx.commit();
  return true;
}

bool Store::record_retryable_failure(long long job_id, const std::string& owner, const ResultRow& r,
                                     int max_attempts) {
  Transaction tx(db_);
  int attempts = 0;
  if (!owned_running(db_, job_id, owner, &attempts)) return false;
  if (attempts < max_attempts) {
    db_.prepare("UPDATE jobs SET status = 'queued', owner = NULL, error = ? WHERE id = ?")
        .bind_all("attempt " + std::to_string(attempts) + ": " + r.reason, job_id).run();
    db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'retry', ?)")
        .bind_all(job_id, r.reason).run();
    tx.commit();
    return true;
  }
  ResultRow final_row = r;
  final_row.status = "failed";
  final_row.reason = r.reason + " (after " + std::to_string(attempts) + " attempts)";
  finish_job(db_, job_id, final_row);
  tx.commit();
  return false;
}

bool Store::release(long long job_id, const std::string& owner, const std::string& why) {
  Transaction tx(db_);
  if (!owned_running(db_, job_id, owner, nullptr)) return false;
  db_.prepare(
         "UPDATE jobs SET status = 'queued', owner = NULL, attempts = MAX(attempts - 1, 0), error = ? "
         "WHERE id = ?")
      .bind_all(why, job_id).run();
  db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'release', ?)").bind_all(job_id, why).run();
  tx.commit();
  return true;
}

int Store::requeue_stale(const std::function<bool(const std::string&)>& alive) {
  Transaction tx(db_);
  std::vector<std::pair<long long, std::string>> stale;
  {
    auto st = db_.prepare("SELECT id, COALESCE(owner, '') FROM jobs WHERE status = 'running'");
    while (st.step())
      if (!alive(st.as_text(1))) stale.emplace_back(st.as_int(0), st.as_text(1));
  }
  for (const auto& [id, owner] : stale) {
    db_.prepare(
           "UPDATE jobs SET status = 'queued', owner = NULL, attempts = MAX(attempts - 1, 0), error = ? "
           "WHERE id = ?")
        .bind_all("requeued: its runner (" + owner + ") is gone", id).run();
    db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'requeue', ?)")
        .bind_all(id, "owner " + owner + " gone").run();
  }
  tx.commit();
  return static_cast<int>(stale.size());
}

void Store::set_job_external_id(long long job_id, const std::string& external_id) {
  db_.prepare("UPDATE jobs SET external_id = ? WHERE id = ?").bind_all(external_id, job_id).run();
}

void Store::set_job_paths(long long job_id, const std::string& result_path) {
  db_.prepare("UPDATE jobs SET result_path = ? WHERE id = ?").bind_all(result_path, job_id).run();
}

}  // namespace gridfree
