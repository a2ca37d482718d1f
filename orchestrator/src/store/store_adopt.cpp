// SPDX-License-Identifier: GPL-3.0-or-later
// Store: adoption of jobs left in an external queue by a process that is
// gone, their queue state, and `retry` of failed jobs (see store.h).
#include "store/store.h"

namespace gridfree {

std::vector<Store::Adopted> Store::take_over_stale(const std::function<bool(const std::string&)>& alive,
                                                   const std::string& owner, const std::string& prefix) {
  Transaction tx(db_);
  std::vector<Adopted> out;
  {
    auto st = db_.prepare(
        "SELECT j.id, COALESCE(j.owner,''), COALESCE(j.external_id,''), j.job_hash, j.spec_json, j.attempts, j.nx, j.ny, j.nz, "
        "COALESCE(j.result_path,''), (SELECT study_id FROM study_jobs WHERE job_id = j.id ORDER BY study_id LIMIT 1) "
        "FROM jobs j WHERE j.status = 'running' "
        "AND (j.external_id IS NULL OR substr(j.external_id, 1, length(?1)) = ?1)");
    st.bind_all(prefix);
    while (st.step()) {
      if (alive(st.as_text(1))) continue;
      Adopted a;
      a.job.job_id = st.as_int(0);
      a.external_id = st.as_text(2);
      a.job.job_hash = st.as_text(3);
      a.job.spec = nlohmann::json::parse(st.as_text(4));
      a.job.attempts = static_cast<int>(st.as_int(5));
      a.job.cells = {static_cast<int>(st.as_int(6)), static_cast<int>(st.as_int(7)), static_cast<int>(st.as_int(8))};
      a.run_dir = std::filesystem::path(st.as_text(9)).parent_path();
      a.job.study_id = st.as_int(10);
      out.push_back(std::move(a));
    }
  }
  for (const auto& a : out) {
    db_.prepare("UPDATE jobs SET owner = ? WHERE id = ?").bind_all(owner, a.job.job_id).run();
    db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'adopt', ?)")
        .bind_all(a.job.job_id, "adopted " + a.external_id + " by " + owner).run();
  }
  tx.commit();
  return out;
}

void Store::set_queue_state(long long job_id, const std::string& external_id, const std::string& state,
                            const std::string& reason) {
  db_.prepare("UPDATE jobs SET external_id = ?, queue_state = ?, queue_reason = NULLIF(?, '') WHERE id = ?")
      .bind_all(external_id, state, reason, job_id).run();
}

std::vector<Store::QueuedJob> Store::queue_jobs(long long study_id) {
  std::vector<QueuedJob> out;
  auto st = db_.prepare(
      "SELECT j.id, j.nx || 'x' || j.ny || 'x' || j.nz, j.external_id, COALESCE(j.queue_state, ''), "
      "COALESCE(j.queue_reason, '') FROM jobs j JOIN study_jobs sj ON sj.job_id = j.id "
      "WHERE sj.study_id = ? AND j.status = 'running' AND j.external_id LIKE 'slurm:%' ORDER BY j.id");
  st.bind_all(study_id);
  while (st.step()) out.push_back({st.as_int(0), st.as_text(1), st.as_text(2), st.as_text(3), st.as_text(4)});
  return out;
}

int Store::retry_failed(long long study_id) {
  Transaction tx(db_);
  std::vector<long long> ids;
  {
    auto st = db_.prepare(
        "SELECT j.id FROM jobs j JOIN study_jobs sj ON sj.job_id = j.id WHERE sj.study_id = ? AND j.status = 'failed'");
    st.bind_all(study_id);
    while (st.step()) ids.push_back(st.as_int(0));
  }
  for (long long id : ids) {
    db_.prepare("UPDATE series SET status = 'queued' WHERE id IN (SELECT series_id FROM study_jobs WHERE job_id = ?)")
        .bind_all(id).run();
    db_.prepare("DELETE FROM results WHERE job_id = ?").bind_all(id).run();
    db_.prepare(
           "UPDATE jobs SET status = 'queued', attempts = 0, owner = NULL, error = NULL, finished_at = NULL, "
           "queue_state = NULL, queue_reason = NULL WHERE id = ?")
        .bind_all(id).run();
    db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'retry', 'requeued by retry')").bind_all(id).run();
  }
  if (!ids.empty())
    db_.prepare("UPDATE studies SET status = 'queued', finished_at = NULL WHERE id = ? AND status <> 'cancelled'")
        .bind_all(study_id).run();
  tx.commit();
  return static_cast<int>(ids.size());
}

}  // namespace gridfree
