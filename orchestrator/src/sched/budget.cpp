// SPDX-License-Identifier: GPL-3.0-or-later
// The budget rule (sched/budget.h).
#include "sched/budget.h"

namespace gridfree {

std::optional<std::size_t> pick_next_job(const std::vector<QueuedJob>& queued, const BudgetUse& in_use,
                                         const BudgetPolicy& policy, HeadReservation& reservation) {
  if (queued.empty() || in_use.jobs >= policy.max_jobs) return std::nullopt;
  const auto fits = [&](const QueuedJob& j) {
    if (in_use.jobs == 0) return true;
    const bool memory = policy.memory_budget_bytes <= 0 || in_use.memory_bytes + j.memory_bytes <= policy.memory_budget_bytes;
    const bool cores = policy.cores <= 0 || in_use.cores + j.cores <= policy.cores;
    return memory && cores;
  };
  std::size_t head = 0;
  for (std::size_t i = 1; i < queued.size(); ++i)
    if (queued[i].memory_bytes > queued[head].memory_bytes) head = i;
  if (fits(queued[head])) {
    reservation = {};
    return head;
  }
  if (reservation.head != queued[head].job_id) reservation = {queued[head].job_id, 0};
  if (reservation.skips >= policy.max_head_skips) return std::nullopt;
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < queued.size(); ++i)
    if (i != head && fits(queued[i]) && (!best || queued[i].memory_bytes > queued[*best].memory_bytes)) best = i;
  if (best) ++reservation.skips;
  return best;
}

}  // namespace gridfree
