// SPDX-License-Identifier: GPL-3.0-or-later
// The gridfree executable run in a folder with the fake worker
// (tests/fixtures/fake_worker.sh) as GRIDFREE_WORKER, for the CLI tests.
#pragma once

#include <spawn.h>
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include "project_paths.h"
#include "run_command.h"

extern char** environ;

namespace gridfree::test_support {

// `gridfree args` run in `dir` with the environment words `env` (such as
// "GRIDFREE_FAKE_SLEEP=0.1") set; stderr kept in dir/stderr.txt.
inline CommandRun gridfree_in(const std::filesystem::path& dir, const std::string& args,
                              const std::string& env = "") {
  return run_command("cd " + shell_quote(dir.string()) + " && GRIDFREE_WORKER=" + shell_quote(kFakeWorker.string()) +
                         " " + env + " " + shell_quote(kGridfreeExe.string()) + " " + args,
                     dir / "stderr.txt");
}

// `gridfree args` started in `dir` like gridfree_in, the fake worker taking
// `fake_sleep` seconds a job (GRIDFREE_FAKE_SLEEP); its output goes to
// dir/<log> (spawned.log). Returns at once with gridfree's pid (the shell execs it).
inline pid_t spawn_gridfree_in(const std::filesystem::path& dir, const std::string& args,
                               const std::string& fake_sleep, const std::string& log = "spawned.log") {
  std::vector<std::string> words = {
      "/bin/sh", "-c",
      "cd " + shell_quote(dir.string()) + " && GRIDFREE_WORKER=" + shell_quote(kFakeWorker.string()) +
          " GRIDFREE_FAKE_SLEEP=" + fake_sleep + " exec " + shell_quote(kGridfreeExe.string()) + " " + args + " >" +
          shell_quote((dir / log).string()) + " 2>&1"};
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
  return pid;
}

}  // namespace gridfree::test_support
