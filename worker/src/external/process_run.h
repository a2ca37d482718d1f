// SPDX-License-Identifier: GPL-3.0-or-later
// Running an external job's command (docs/EXTERNAL.md "How the driver runs
// your code"): setup lines and argv, in the case folder, stdin from
// /dev/null, stdout and stderr into two files, watched until it ends or a
// stop is requested.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct CommandLaunch {
  std::vector<std::string> setup;    // shell lines run first (in one /bin/sh, `set -e`)
  std::vector<std::string> command;  // argv
  std::filesystem::path cwd;
  std::filesystem::path stdout_file;
  std::filesystem::path stderr_file;
};

// The argv actually exec'd: the command itself without setup lines, else
//   /bin/sh -c 'set -e\n<setup lines>\nexec "$@"' gridfree-setup <command...>
std::vector<std::string> launch_argv(const CommandLaunch& launch);

struct CommandEnd {
  std::optional<int> exit_code;  // it exited
  std::optional<int> signal;     // it was killed by this signal
  bool stopped = false;          // a stop was requested: it was sent SIGTERM (then SIGKILL)
  double wall_s = 0;
  double cpu_s = 0;              // user + system of it and its waited-for descendants
  double peak_rss_mb = 0;        // the largest resident set among them
};

struct CommandWatch {
  std::function<bool()> stop_requested;           // polled every 20-100 ms
  std::function<void(double elapsed_s)> on_tick;  // every ~2 s
  double stop_grace_s = 10;                       // SIGTERM → SIGKILL
};

// Runs the command and waits for it. When the worker leads its own process
// group (as the orchestrator starts it), the command stays in that group, so
// the orchestrator's kill of the group reaches it; otherwise it gets a
// group of its own. A stop request sends SIGTERM to the command's group,
// then SIGKILL after the grace. Throws std::runtime_error when it cannot fork
// or open the log files.
CommandEnd run_command_watched(const CommandLaunch& launch, const CommandWatch& watch);

}  // namespace gridfree
