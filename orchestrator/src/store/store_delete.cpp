// SPDX-License-Identifier: GPL-3.0-or-later
// Store: removing a study (gridfree delete, run --replace) and, for
// delete, those of its jobs no other study uses (store/unneeded_jobs.h).
#include "core/input_error.h"
#include "store/store.h"
#include "store/unneeded_jobs.h"

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

std::vector<long long> Store::study_job_ids(long long study_id) {
  std::vector<long long> ids;
  auto st = db_.prepare("SELECT DISTINCT job_id FROM study_jobs WHERE study_id = ? ORDER BY job_id");
  st.bind_all(study_id);
  while (st.step()) ids.push_back(st.as_int(0));
  return ids;
}

std::optional<std::vector<std::string>> Store::delete_study(const std::string& name) {
  Transaction tx(db_);
  const auto id = study_id(name);
  if (!id) return std::nullopt;
  const std::vector<long long> jobs = study_job_ids(*id);
  remove_study_rows(*id, name);
  auto removed = remove_unlinked_jobs(db_, jobs);
  db_.prepare("INSERT INTO events(kind, message) VALUES ('delete', ?)")
      .bind_all("study '" + name + "' deleted; " + std::to_string(removed.size()) + " job(s) no other study uses removed")
      .run();
  tx.commit();
  return removed;
}

}  // namespace gridfree
