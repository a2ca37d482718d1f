// SPDX-License-Identifier: GPL-3.0-or-later
// StudyFactsCache (sched/study_facts.h).
#include "sched/study_facts.h"

#include "study/adaptive_grids.h"
#include "study/job_cores.h"

namespace gridfree {

const StudyFacts& StudyFactsCache::of(long long study_id) {
  auto it = facts_.find(study_id);
  if (it != facts_.end()) return it->second;
  StudyFacts f;
  const nlohmann::json d = store_.study_definition(study_id);
  if (d.is_object()) {
    if (const auto t = d.find("timeout_s"); t != d.end() && t->is_number()) f.timeout_s = t->get<double>();
    f.cores = study_cores_expression(d);
  }
  f.adaptive = adaptive_grids_of(d).has_value();
  f.external_costs = declared_external_costs(d);
  f.external = !f.external_costs.empty();
  return facts_.emplace(study_id, f).first->second;
}

}  // namespace gridfree
