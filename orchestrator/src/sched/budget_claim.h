// Claims the job the budget rule picks (sched/budget.h) from the queued
// jobs of one study (or of every active study).
#pragma once

#include <optional>
#include <string>

#include "sched/budget.h"
#include "store/store.h"

namespace gridfree {

// The first queued job of each grid size in each study in scope, in queue
// order, with need(job) from its cells (the only candidates the rule picks).
std::vector<QueuedJob> queued_jobs(Store& store, std::optional<long long> study);

// nullopt: nothing may start now (or another process claimed the pick first;
// the next round tries again).
std::optional<ClaimedJob> claim_within_budget(Store& store, std::optional<long long> study, const std::string& owner,
                                              const BudgetUse& in_use, const BudgetPolicy& policy,
                                              HeadReservation& reservation);

}  // namespace gridfree
