// SPDX-License-Identifier: GPL-3.0-or-later
// Estimates of external jobs for the scheduler loop (study/external_plan.h):
// the declared figures of their study, else the measured history of their
// case, read from the database once and extended as the loop's jobs finish.
#pragma once

#include <array>
#include <optional>

#include "sched/study_facts.h"
#include "store/store.h"
#include "study/cost_model.h"
#include "study/external_plan.h"

namespace gridfree {

class ExternalEstimates {
 public:
  ExternalEstimates(Store& store, StudyFactsCache& facts) : store_(store), facts_(facts) {}
  // nullopt for gridfree's own jobs.
  std::optional<ExternalJobCost> of(const ClaimedJob& job);
  // need(job) of the memory budget (sched/budget.h): the worker's model for
  // gridfree's own jobs; NaN for an external job of unknown memory.
  double need(const ClaimedJob& job);
  double need(long long study_id, long long job_id, const std::array<int, 3>& cells);
  // A finished external job's measurement, for the jobs that follow.
  void finished(const ClaimedJob& job, const ResultRow& row);

 private:
  CostHistory& history();
  Store& store_;
  StudyFactsCache& facts_;
  std::optional<CostHistory> history_;
};

}  // namespace gridfree
