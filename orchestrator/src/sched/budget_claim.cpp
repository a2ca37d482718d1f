// Budgeted claims (sched/budget_claim.h).
#include "sched/budget_claim.h"

#include "job/memory_estimate.h"

namespace gridfree {

// Jobs of one grid size need the same memory, so the rule (sched/budget.h)
// only ever picks the first of each size in queue order: one row per study
// and size is read, not the whole queue (tens of thousands of jobs in an
// ensemble study, and a claim for every start).
std::vector<QueuedJob> queued_jobs(Store& store, std::optional<long long> study) {
  auto st = store.db().prepare(
      "SELECT MIN(j.id), j.nx, j.ny, j.nz FROM jobs j JOIN study_jobs sj ON sj.job_id = j.id "
      "JOIN studies s ON s.id = sj.study_id "
      "WHERE j.status = 'queued' AND s.status IN ('queued','running') AND (?1 IS NULL OR s.id = ?1) "
      "GROUP BY s.id, j.nx, j.ny, j.nz "
      "ORDER BY s.id, MAX(j.cells) DESC, MIN(j.id)");
  st.bind_all(study);
  std::vector<QueuedJob> out;
  while (st.step()) {
    const std::array<int, 3> cells{static_cast<int>(st.as_int(1)), static_cast<int>(st.as_int(2)),
                                   static_cast<int>(st.as_int(3))};
    out.push_back({st.as_int(0), job_memory_estimate_bytes(cells)});
  }
  return out;
}

std::optional<ClaimedJob> claim_within_budget(Store& store, std::optional<long long> study, const std::string& owner,
                                              const BudgetUse& in_use, const BudgetPolicy& policy,
                                              HeadReservation& reservation) {
  const auto queued = queued_jobs(store, study);
  const auto pick = pick_next_job(queued, in_use, policy, reservation);
  if (!pick) return std::nullopt;
  return store.claim_next(study, owner, queued[*pick].job_id);
}

}  // namespace gridfree
