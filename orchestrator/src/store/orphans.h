// SPDX-License-Identifier: GPL-3.0-or-later
// Jobs the database shows as running whose claimant process is gone (a
// `run` or `daemon` killed): read-only, with the same test a starting
// `run`/`daemon` uses to requeue or adopt them (owner_alive, store/owner.h).
// `status` shows them as orphaned rather than running.
#pragma once

#include <map>
#include <optional>
#include <set>

#include "store/store.h"

namespace gridfree {

struct RunningJobs {
  std::set<long long> live;      // claimed by a process that still exists (or on another host)
  std::set<long long> orphaned;  // claimed by a process that is gone
};

// By study id; only studies with running jobs appear. `study`: one study.
std::map<long long, RunningJobs> running_jobs_by_study(Store& store, std::optional<long long> study = std::nullopt);

}  // namespace gridfree
