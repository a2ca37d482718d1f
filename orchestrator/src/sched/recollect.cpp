// SPDX-License-Identifier: GPL-3.0-or-later
// Re-collection of finished external jobs (sched/recollect.h).
#include "sched/recollect.h"

#include "exec/executor.h"
#include "exec/process_run.h"
#include "sched/external_result.h"
#include "sched/outcome.h"

namespace gridfree {

RecollectSummary recollect_study(Store& store, long long study_id, const std::filesystem::path& worker,
                                 const std::filesystem::path& runs_root) {
  RecollectSummary sum;
  for (const auto& job : store.jobs_to_recollect(study_id)) {
    // job.json now holds the study's collect section; the run's case/ stays.
    // The job's run folder is where it ran (its recorded result path, also
    // when that run had another --runs-dir), else under runs_root.
    std::filesystem::path root = runs_root;
    {
      auto st = store.db().prepare("SELECT COALESCE(result_path, '') FROM jobs WHERE id = ?");
      st.bind_all(job.job_id);
      const std::filesystem::path recorded = st.step() ? std::filesystem::path(st.as_text(0)) : std::filesystem::path();
      if (!recorded.empty() && recorded.parent_path().filename() == job.job_hash)
        root = recorded.parent_path().parent_path().parent_path();
    }
    const auto dir = prepare_run_dir(root, job.job_hash, job.spec.dump());
    const auto result = dir / "result.json";
    const ProcessOutput p = run_process({worker.string(), "collect", (dir / "job.json").string(), "-o",
                                         result.string(), "--run-dir", dir.string()});
    try {
      if (p.exit_code != 0 && p.exit_code != 3)
        throw std::runtime_error("gridfree-worker collect exited with " + std::to_string(p.exit_code) + ": " +
                                 p.err.substr(0, 500));
      ResultRow row = read_result_file(result);
      note_collect_spec(job.spec, row);
      store.record_recollected(job.job_id, row);
      ++sum.recollected;
    } catch (const std::exception& e) {
      ++sum.failed;
      if (sum.first_error.empty()) sum.first_error = job.job_hash.substr(0, 12) + ": " + e.what();
    }
  }
  return sum;
}

}  // namespace gridfree
