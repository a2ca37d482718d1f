// SPDX-License-Identifier: GPL-3.0-or-later
// ExternalEstimates (sched/external_estimates.h).
#include "sched/external_estimates.h"

#include "job/memory_estimate.h"
#include "sched/cost_history.h"
#include "sched/external_result.h"
#include "study/case_kind.h"

namespace gridfree {

std::optional<ExternalJobCost> ExternalEstimates::of(const ClaimedJob& job) {
  const CaseKind& kind = case_kind_of_job(job.spec);
  return kind.own_cost(job.spec, job.cells, facts_.of(job.study_id).external_costs, history());
}

double ExternalEstimates::need(const ClaimedJob& job) {
  const auto c = of(job);
  return c ? c->memory_bytes : job_memory_estimate_bytes(job.cells);
}

double ExternalEstimates::need(long long study_id, long long job_id, const std::array<int, 3>& cells) {
  if (!facts_.of(study_id).external) return job_memory_estimate_bytes(cells);
  auto st = store_.db().prepare("SELECT spec_json FROM jobs WHERE id = ?");
  st.bind_all(job_id);
  if (!st.step()) return job_memory_estimate_bytes(cells);
  ClaimedJob job;
  job.job_id = job_id;
  job.study_id = study_id;
  job.spec = nlohmann::json::parse(st.as_text(0), nullptr, false);
  job.cells = cells;
  return need(job);
}

void ExternalEstimates::finished(const ClaimedJob& job, const ResultRow& row) {
  if (!is_external_job(job.spec) || row.status != "converged" || !(row.cpu_s > 0 || row.peak_rss_mb > 0)) return;
  const double cells = static_cast<double>(job.cells[0]) * job.cells[1] * job.cells[2];
  history()[cost_similarity_key(job.spec)].push_back({cells, row.cpu_s, row.peak_rss_mb});
}

CostHistory& ExternalEstimates::history() {
  if (!history_) history_ = read_cost_history(store_.db(), true);
  return *history_;
}

}  // namespace gridfree
