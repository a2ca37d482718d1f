// SPDX-License-Identifier: GPL-3.0-or-later
// Claims the job the budget rule picks (sched/budget.h) from the queued
// jobs of one study (or of every active study).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>

#include "sched/budget.h"
#include "store/store.h"

namespace gridfree {

// need(job) of a queued job: (study id, job id, cells) → bytes; NaN when
// unknown (an external code without a declared or measured figure,
// docs/EXTERNAL.md "Cost"). Empty: the worker's model of the cells.
using NeedOf = std::function<double(long long study_id, long long job_id, const std::array<int, 3>& cells)>;

// cores(job) of a queued job (study/job_cores.h): (study id, cells) → cores.
// Empty: 1.
using CoresOf = std::function<int(long long study_id, const std::array<int, 3>& cells)>;

// The first queued job of each grid size in each study in scope, in queue
// order (largest first; jobs of unknown need smallest first), with
// need(job) and cores(job) (the only candidates the rule picks).
std::vector<QueuedJob> queued_jobs(Store& store, std::optional<long long> study, const NeedOf& need = {},
                                   const CoresOf& cores = {});

// need(job) as the budget counts it: an unknown need (NaN) is the whole
// memory budget, so that such a job runs alone (0 without a budget).
double counted_need(double need_bytes, const BudgetPolicy& policy);

// nullopt: nothing may start now (or another process claimed the pick first;
// the next round tries again).
std::optional<ClaimedJob> claim_within_budget(Store& store, std::optional<long long> study, const std::string& owner,
                                              const BudgetUse& in_use, const BudgetPolicy& policy,
                                              HeadReservation& reservation, const NeedOf& need = {},
                                              const CoresOf& cores = {});

}  // namespace gridfree
