// SPDX-License-Identifier: GPL-3.0-or-later
// Who claimed a job: "host:pid:starttime". The start time (from
// /proc/<pid>/stat) tells a live claimant from a recycled pid, so a restart
// can requeue exactly the jobs whose owner process is gone.
#pragma once

#include <string>

namespace gridfree {

std::string this_process_owner();

// False when the owner ran on this host and that process no longer exists
// (or its pid now belongs to another process). Owners on other hosts, or
// unparsable ones, count as alive unless `assume_other_hosts_dead`.
bool owner_alive(const std::string& owner, bool assume_other_hosts_dead = false);

}  // namespace gridfree
