// SPDX-License-Identifier: GPL-3.0-or-later
// Identity of a process on this machine, robust to pid reuse:
// "host:pid:starttime", the start time being field 22 of /proc/<pid>/stat.
#pragma once

#include <string>

namespace gridfree {

std::string host_name();  // gethostname(), "localhost" if unavailable

// Start time of process `pid` in clock ticks since boot, "" if there is none.
std::string process_start_time(long pid);

// "host:pid:starttime" of process `pid` on this host.
std::string process_identity_string(long pid);

}  // namespace gridfree
