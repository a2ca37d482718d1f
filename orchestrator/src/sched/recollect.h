// SPDX-License-Identifier: GPL-3.0-or-later
// Re-collection of external jobs (docs/EXTERNAL.md "The study"): when a
// study's collect section changed for jobs that are already finished, each
// is read again from its run folder with `gridfree-worker collect JOB.json
// -o RESULT.json --run-dir DIR` (no solver run) and the new values are
// stored (Store::record_recollected). `run` and `submit` re-collect after
// storing the study; `daemon` when it starts, for the active studies (a
// submit whose re-collection failed, e.g. without the worker).
#pragma once

#include <filesystem>
#include <string>

#include "store/store.h"

namespace gridfree {

struct RecollectSummary {
  int recollected = 0;  // results replaced
  int failed = 0;       // the collect command failed (the old result stays)
  std::string first_error;
};

RecollectSummary recollect_study(Store& store, long long study_id, const std::filesystem::path& worker,
                                 const std::filesystem::path& runs_root);

}  // namespace gridfree
