// SPDX-License-Identifier: GPL-3.0-or-later
// Adoption of stale jobs (see adopt.h).
#include "sched/adopt.h"

#include <spdlog/spdlog.h>

#include "store/owner.h"

namespace gridfree {

std::vector<ClaimedJob> adopt_stale_jobs(Store& store, Executor& executor, const std::string& owner,
                                         double timeout_s, const std::string& prefix) {
  std::vector<ClaimedJob> adopted;
  for (auto& a : store.take_over_stale([](const std::string& o) { return owner_alive(o); }, owner, prefix)) {
    JobLaunch launch;
    launch.job_id = a.job.job_id;
    launch.job_hash = a.job.job_hash;
    launch.run_dir = a.run_dir;
    launch.cells = a.job.cells;
    launch.timeout_s = timeout_s;
    if (!a.run_dir.empty() && executor.adopt(launch, a.external_id)) {
      adopted.push_back(std::move(a.job));
    } else {
      store.release(a.job.job_id, owner,
                    a.external_id.empty() ? "requeued: never submitted"
                                          : "requeued: " + a.external_id + " cannot be watched by this executor");
    }
  }
  if (!adopted.empty()) spdlog::info("adopted {} job(s) left in the queue by a process that is gone", adopted.size());
  return adopted;
}

}  // namespace gridfree
