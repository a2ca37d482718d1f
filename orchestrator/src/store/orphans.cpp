// SPDX-License-Identifier: GPL-3.0-or-later
// Running jobs by whether their claimant lives (see orphans.h).
#include "store/orphans.h"

#include "store/owner.h"

namespace gridfree {

std::map<long long, RunningJobs> running_jobs_by_study(Store& store, std::optional<long long> study) {
  std::map<long long, RunningJobs> out;
  auto st = store.db().prepare(
      "SELECT DISTINCT sj.study_id, j.id, COALESCE(j.owner, '') FROM jobs j JOIN study_jobs sj ON sj.job_id = j.id "
      "WHERE j.status = 'running' AND (?1 IS NULL OR sj.study_id = ?1)");
  st.bind_all(study ? std::optional<long long>(*study) : std::optional<long long>());
  while (st.step()) {
    auto& r = out[st.as_int(0)];
    (owner_alive(st.as_text(2)) ? r.live : r.orphaned).insert(st.as_int(1));
  }
  return out;
}

}  // namespace gridfree
