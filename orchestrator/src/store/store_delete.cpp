// SPDX-License-Identifier: GPL-3.0-or-later
// Store: removing a study (gridfree delete, run --replace) and collecting
// the jobs no study needs any more.
#include "core/input_error.h"
#include "store/store.h"

namespace gridfree {

void Store::remove_study_rows(long long study_id, const std::string& name) {
  auto running = db_.prepare(
      "SELECT COUNT(*) FROM jobs WHERE status = 'running' AND id IN "
      "(SELECT job_id FROM study_jobs WHERE study_id = ?)");
  running.bind_all(study_id);
  running.step();
  if (const long long n = running.as_int(0); n > 0)
    throw InputError("STUDY", "study '" + name + "' has " + std::to_string(n) +
                                  " running job(s); stop the run or daemon working it (or wait) and try again");
  const char* per_series[] = {
      "DELETE FROM uncertainties WHERE series_id IN (SELECT id FROM series WHERE study_id = ?)",
      "DELETE FROM extrapolations WHERE series_id IN (SELECT id FROM series WHERE study_id = ?)",
      "DELETE FROM study_jobs WHERE study_id = ?",
      "DELETE FROM series WHERE study_id = ?",
      "DELETE FROM events WHERE study_id = ?",
      "DELETE FROM studies WHERE id = ?",
  };
  for (const char* sql : per_series) db_.prepare(sql).bind_all(study_id).run();
}

std::vector<std::string> Store::remove_orphan_jobs() {
  // Orphans: jobs no study links (never running: a running job's study
  // cannot be removed, and a job is linked before it can be claimed).
  const char* orphans = "SELECT id FROM jobs WHERE id NOT IN (SELECT job_id FROM study_jobs)";
  std::vector<std::string> hashes;
  auto list = db_.prepare(std::string("SELECT job_hash FROM jobs WHERE id IN (") + orphans + ")");
  while (list.step()) hashes.push_back(list.as_text(0));
  db_.prepare(std::string("DELETE FROM uncertainties WHERE job_id IN (") + orphans + ")").run();
  db_.prepare(std::string("DELETE FROM results WHERE job_id IN (") + orphans + ")").run();
  // their events too ('result' and the like carry only the job id, no study id),
  // or they would dangle and attach to a later job given the same id
  db_.prepare(std::string("DELETE FROM events WHERE job_id IN (") + orphans + ")").run();
  db_.prepare(std::string("DELETE FROM jobs WHERE id IN (") + orphans + ")").run();
  return hashes;
}

std::optional<std::vector<std::string>> Store::delete_study(const std::string& name) {
  Transaction tx(db_);
  const auto id = study_id(name);
  if (!id) return std::nullopt;
  remove_study_rows(*id, name);
  auto removed = remove_orphan_jobs();
  db_.prepare("INSERT INTO events(kind, message) VALUES ('delete', ?)")
      .bind_all("study '" + name + "' deleted; " + std::to_string(removed.size()) + " job(s) no other study uses removed")
      .run();
  tx.commit();
  return removed;
}

}  // namespace gridfree
