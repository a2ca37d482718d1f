// SPDX-License-Identifier: GPL-3.0-or-later
// Command names as users type them (docs/INTERFACE.md §3): a mistyped command
// names the nearest one (exit 2), `version` and -V print the version, each
// executable's --version names itself, and `help COMMAND` is COMMAND --help.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::run_executable;

fs::path names_dir(const std::string& name) {
  return gridfree::test_support::fresh_scratch_dir("command_names_cli", name);
}

TEST(CommandNamesCli, MistypedCommandSuggestsTheNearest) {
  const fs::path dir = names_dir("typo");
  const CommandRun r = run_executable("gridfree", "stauts", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown command 'stauts'; did you mean 'status'?"), std::string::npos) << r.err;
  const CommandRun far = run_executable("gridfree", "xyzzyq", dir);
  EXPECT_EQ(far.exit_code, 2) << far.err;
  EXPECT_NE(far.err.find("unknown command 'xyzzyq'; commands:"), std::string::npos) << far.err;
  const CommandRun worker = run_executable("gridfree-worker", "slove", dir);
  EXPECT_EQ(worker.exit_code, 2) << worker.err;
  EXPECT_NE(worker.err.find("did you mean 'solve'?"), std::string::npos) << worker.err;
}

TEST(CommandNamesCli, VersionWordAndShortFlagPrintTheVersion) {
  const fs::path dir = names_dir("version");
  const CommandRun flag = run_executable("gridfree", "--version", dir);
  ASSERT_EQ(flag.exit_code, 0) << flag.err;
  EXPECT_EQ(flag.out.rfind("gridfree ", 0), 0u) << flag.out;
  for (const char* args : {"version", "-V"}) {
    const CommandRun r = run_executable("gridfree", args, dir);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_EQ(r.out, flag.out) << args;
  }
}

TEST(CommandNamesCli, WorkerVersionNamesTheWorker) {
  const fs::path dir = names_dir("worker_version");
  for (const char* args : {"--version", "-V", "version"}) {
    const CommandRun r = run_executable("gridfree-worker", args, dir);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_EQ(r.out.rfind("gridfree-worker ", 0), 0u) << args << ": " << r.out;
  }
}

TEST(CommandNamesCli, WorkerVerifyRefusesGridsThatDoNotIncrease) {
  const fs::path dir = names_dir("verify_grids");
  for (const char* args : {"verify --grids 16 8", "verify --grids 2 8"}) {
    const CommandRun r = run_executable("gridfree-worker", args, dir);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("--grids"), std::string::npos) << args << ": " << r.err;
  }
}

TEST(CommandNamesCli, ExecutorHelpListsItsChoices) {
  const fs::path dir = names_dir("executor_help");
  const CommandRun r = run_executable("gridfree", "run --help", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("{local,slurm}"), std::string::npos) << r.out;
}

TEST(CommandNamesCli, HelpCommandIsTheCommandsHelp) {
  const fs::path dir = names_dir("help_command");
  const CommandRun flag = run_executable("gridfree", "run --help", dir);
  const CommandRun word = run_executable("gridfree", "help run", dir);
  EXPECT_EQ(word.exit_code, 0) << word.err;
  EXPECT_EQ(word.out, flag.out);
  EXPECT_NE(word.out.find("STUDY"), std::string::npos) << word.out;
  const CommandRun top = run_executable("gridfree", "help", dir);
  EXPECT_EQ(top.exit_code, 0) << top.err;
  EXPECT_EQ(top.out, run_executable("gridfree", "--help", dir).out);
  const CommandRun typo = run_executable("gridfree", "help stauts", dir);
  EXPECT_EQ(typo.exit_code, 2) << typo.err;
  EXPECT_NE(typo.err.find("did you mean 'status'?"), std::string::npos) << typo.err;
}

}  // namespace
