// SPDX-License-Identifier: GPL-3.0-or-later
// What the scheduler loop needs from a study's definition, parsed once per
// study and process (a definition grows with its cases; parsing it per job
// would make the cost per job grow with the study).
#pragma once

#include <map>
#include <optional>
#include <string>

#include "sched/external_result.h"
#include "store/store.h"

namespace gridfree {

struct StudyFacts {
  std::optional<double> timeout_s;  // the definition's timeout_s
  bool adaptive = false;            // adaptive grids (study/adaptive_grids.h)
  bool external = false;            // its cases are external (docs/EXTERNAL.md)
  std::string cores;                // the definition's cores expression (study/job_cores.h); "" = none
  std::map<std::string, DeclaredCost> external_costs;  // external cases' declared cost (study/external_cost.h)
};

class StudyFactsCache {
 public:
  explicit StudyFactsCache(Store& store) : store_(store) {}
  const StudyFacts& of(long long study_id);

 private:
  Store& store_;
  std::map<long long, StudyFacts> facts_;
};

}  // namespace gridfree
