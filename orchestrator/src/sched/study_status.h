// SPDX-License-Identifier: GPL-3.0-or-later
// What `gridfree status STUDY` shows inside a study (docs/ORCHESTRATOR.md):
// per series the grids done, verdict, f0 and the finest grid's RDE; per
// running job its grid, cells and the worker's latest progress (read from
// <run folder>/progress.json, written by `gridfree-worker solve --progress`)
// with the log path; and the ETA of study_eta.h (cost model × measured).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "exec/worker_progress.h"
#include "store/store.h"

namespace gridfree {

// {"series": [...], "running": [...], "eta": {...}} for one study; run
// folders are exec/executor.h's run_dir_for(runs_root, job_hash). `workers`
// = jobs at a time for the ETA (the running count when 0).
nlohmann::json study_detail(Store& store, long long study_id, const std::filesystem::path& runs_root,
                            int workers = 0);

// The detail as aligned text tables.
std::string study_detail_text(const nlohmann::json& detail);

}  // namespace gridfree
