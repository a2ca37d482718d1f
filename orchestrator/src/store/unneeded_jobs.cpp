// SPDX-License-Identifier: GPL-3.0-or-later
// Jobs no study needs any more (store/unneeded_jobs.h).
#include "store/unneeded_jobs.h"

namespace gridfree {
namespace {

bool linked(Database& db, long long job_id) {
  auto st = db.prepare("SELECT 1 FROM study_jobs WHERE job_id = ? LIMIT 1");
  st.bind_all(job_id);
  return st.step();
}

std::string job_hash_of(Database& db, long long job_id) {
  auto st = db.prepare("SELECT job_hash FROM jobs WHERE id = ?");
  st.bind_all(job_id);
  return st.step() ? st.as_text(0) : std::string();
}

}  // namespace

std::vector<UnneededJob> unneeded_jobs(Database& db) {
  std::vector<UnneededJob> out;
  auto st = db.prepare(
      "SELECT id, job_hash, status, COALESCE(CASE WHEN json_valid(spec_json) THEN json_extract(spec_json, '$.case.name') END, ''), COALESCE(cells, 0) "
      "FROM jobs WHERE NOT EXISTS (SELECT 1 FROM study_jobs sj WHERE sj.job_id = jobs.id) ORDER BY id");
  while (st.step()) out.push_back({st.as_int(0), st.as_text(1), st.as_text(2), st.as_text(3), st.as_int(4)});
  return out;
}

std::vector<std::string> keep_unlinked_jobs(Database& db, const std::vector<long long>& candidates) {
  std::vector<std::string> hashes;
  for (long long id : candidates) {
    if (linked(db, id)) continue;
    const std::string hash = job_hash_of(db, id);
    if (hash.empty()) continue;
    db.prepare("UPDATE jobs SET status = 'cancelled', error = 'no study needs it' WHERE id = ? AND status = 'queued'")
        .bind_all(id)
        .run();
    hashes.push_back(hash);
  }
  return hashes;
}

std::vector<std::string> remove_unlinked_jobs(Database& db, const std::vector<long long>& candidates) {
  // Never running: a running job's study cannot be removed, and a job is
  // linked before it can be claimed.
  std::vector<std::string> hashes;
  for (long long id : candidates) {
    if (linked(db, id)) continue;
    const std::string hash = job_hash_of(db, id);
    if (hash.empty()) continue;
    db.prepare("DELETE FROM uncertainties WHERE job_id = ?").bind_all(id).run();
    db.prepare("DELETE FROM results WHERE job_id = ?").bind_all(id).run();
    // its events too ('result' and the like carry only the job id), or they
    // would dangle and attach to a later job given the same id
    db.prepare("DELETE FROM events WHERE job_id = ?").bind_all(id).run();
    db.prepare("DELETE FROM jobs WHERE id = ?").bind_all(id).run();
    hashes.push_back(hash);
  }
  return hashes;
}

std::vector<UnneededJob> remove_unneeded_jobs(Store& store) {
  Transaction tx(store.db());
  const std::vector<UnneededJob> jobs = unneeded_jobs(store.db());
  std::vector<long long> ids;
  for (const auto& j : jobs) ids.push_back(j.id);
  remove_unlinked_jobs(store.db(), ids);
  store.db()
      .prepare("INSERT INTO events(kind, message) VALUES ('gc', ?)")
      .bind_all("gc: " + std::to_string(jobs.size()) + " job(s) no study needs removed")
      .run();
  tx.commit();
  return jobs;
}

bool job_hash_stored(Database& db, const std::string& hash) {
  auto st = db.prepare("SELECT 1 FROM jobs WHERE job_hash = ?");
  st.bind_all(hash);
  return st.step();
}

}  // namespace gridfree
