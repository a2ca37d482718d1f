// SPDX-License-Identifier: GPL-3.0-or-later
// Budgeted claims (sched/budget_claim.h).
#include "sched/budget_claim.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "job/memory_estimate.h"

namespace gridfree {

namespace {

// Jobs of one grid size need the same memory, so the rule (sched/budget.h)
// only ever picks the first of each size in queue order: one row per study
// and size is read, not the whole queue (tens of thousands of jobs in an
// ensemble study, and a claim for every start). Both steps are seeks in the
// index jobs(status, nx, ny, nz, id) (schema step 9): the queued sizes one
// after the other (a loose index scan), then per size and study its first
// queued job, found at the front of the size's queue when one study runs.
//
// The next size after (a, b, c) is the first of: nx = a, ny = b, nz > c;
// nx = a, ny > b; nx > a: three seeks. One row-value test (nx, ny, nz) >
// (a, b, c) would seek on nx ≥ a only and step over every queued job of
// the size just found (2 778 rows per size in a 50 004-job study: the
// claims' cost grew with the study).
std::vector<std::array<long long, 3>> queued_sizes(Store& store) {
  auto same_xy = store.db().prepare(
      "SELECT nx, ny, nz FROM jobs INDEXED BY jobs_queue WHERE status = 'queued' AND nx = ? AND ny = ? AND nz > ? "
      "ORDER BY nx, ny, nz LIMIT 1");
  auto same_x = store.db().prepare(
      "SELECT nx, ny, nz FROM jobs INDEXED BY jobs_queue WHERE status = 'queued' AND nx = ? AND ny > ? "
      "ORDER BY nx, ny, nz LIMIT 1");
  auto larger_x = store.db().prepare(
      "SELECT nx, ny, nz FROM jobs INDEXED BY jobs_queue WHERE status = 'queued' AND nx > ? "
      "ORDER BY nx, ny, nz LIMIT 1");
  std::vector<std::array<long long, 3>> sizes;
  std::array<long long, 3> after{-1, -1, -1};
  for (;;) {
    same_xy.reset();
    same_xy.bind_all(after[0], after[1], after[2]);
    same_x.reset();
    same_x.bind_all(after[0], after[1]);
    larger_x.reset();
    larger_x.bind_all(after[0]);
    Statement* found = same_xy.step() ? &same_xy : same_x.step() ? &same_x : larger_x.step() ? &larger_x : nullptr;
    if (!found) break;
    after = {found->as_int(0), found->as_int(1), found->as_int(2)};
    sizes.push_back(after);
  }
  return sizes;
}

}  // namespace

std::vector<QueuedJob> queued_jobs(Store& store, std::optional<long long> study, const NeedOf& need,
                                   const CoresOf& cores) {
  const std::vector<std::array<long long, 3>> sizes = queued_sizes(store);
  std::vector<long long> studies = store.active_studies();
  if (study) studies.erase(std::remove_if(studies.begin(), studies.end(), [&](long long id) { return id != *study; }),
                           studies.end());
  // The size's queued jobs in id order, each checked for the study by its
  // job_id ("+": not through the study's index, which reads all its rows).
  auto first = store.db().prepare(
      "SELECT j.id FROM jobs j INDEXED BY jobs_queue "
      "WHERE j.status = 'queued' AND j.nx = ? AND j.ny = ? AND j.nz = ? "
      "AND EXISTS (SELECT 1 FROM study_jobs sj WHERE sj.job_id = j.id AND +sj.study_id = ?) "
      "ORDER BY j.id LIMIT 1");
  struct Row {
    long long study, cells, id;
    std::array<int, 3> size;
    double need;
    int cores;
  };
  std::vector<Row> rows;
  for (long long id : studies)
    for (const auto& z : sizes) {
      first.reset();
      first.bind_all(z[0], z[1], z[2], id);
      if (!first.step()) continue;
      const std::array<int, 3> cells{static_cast<int>(z[0]), static_cast<int>(z[1]), static_cast<int>(z[2])};
      const long long job = first.as_int(0);
      rows.push_back({id, z[0] * z[1] * z[2], job, cells, need ? need(id, job, cells) : job_memory_estimate_bytes(cells),
                      cores ? cores(id, cells) : 1});
    }
  // An unknown need runs alone: the smallest such job first, so that its
  // measured peak gives the others an estimate soonest.
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    if (a.study != b.study) return a.study < b.study;
    const bool ua = std::isnan(a.need), ub = std::isnan(b.need);
    if (ua != ub) return ua;
    if (a.cells != b.cells) return ua ? a.cells < b.cells : a.cells > b.cells;
    return a.id < b.id;
  });
  std::vector<QueuedJob> out;
  for (const auto& r : rows) out.push_back({r.id, r.need, r.cores});
  return out;
}

double counted_need(double need_bytes, const BudgetPolicy& policy) {
  return std::isnan(need_bytes) ? policy.memory_budget_bytes : need_bytes;
}

std::optional<ClaimedJob> claim_within_budget(Store& store, std::optional<long long> study, const std::string& owner,
                                              const BudgetUse& in_use, const BudgetPolicy& policy,
                                              HeadReservation& reservation, const NeedOf& need,
                                              const CoresOf& cores) {
  auto queued = queued_jobs(store, study, need, cores);
  for (auto& q : queued) q.memory_bytes = counted_need(q.memory_bytes, policy);
  const auto pick = pick_next_job(queued, in_use, policy, reservation);
  if (!pick) return std::nullopt;
  return store.claim_next(study, owner, queued[*pick].job_id);
}

}  // namespace gridfree
