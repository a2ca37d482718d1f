// SPDX-License-Identifier: GPL-3.0-or-later
// Command names as users type them (docs/INTERFACE.md §3): a mistyped command
// names the nearest one (exit 2), `version` and -V print the version, each
// executable's --version names itself, and `help COMMAND` is COMMAND --help.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

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

// One error style (cli_errors.h): every failure a user causes prints lines
// starting "error: ", the parser's own messages included, points at the
// command's help, and never prints the path the program ran from; `help run`
// puts the Slurm flags under their own heading.
TEST(CommandNamesCli, EveryUserErrorHasOneStyleWithoutTheBuildPath) {
  const fs::path dir = names_dir("error_style");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "error: a subcommand is required\nrun 'gridfree --help' for the options"},
      {"run", "error: STUDY is required\nrun 'gridfree run --help' for the options"},
      {"run --jobs x s.json", "error: could not convert: --jobs = x"},
      {"runn", "error: unknown command 'runn'; did you mean 'run'?\nrun 'gridfree --help' for the commands"},
      {"validate missing.json", "error: missing.json: "}};
  for (const auto& [args, expected] : cases) {
    const CommandRun r = run_executable("gridfree", args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind(expected, 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(r.err.find('/'), std::string::npos) << "a path in: " << r.err;
    for (std::size_t at = 0; at < r.err.size();) {  // every line an error or the help pointer
      const std::string line = r.err.substr(at, r.err.find('\n', at) - at);
      EXPECT_TRUE(line.rfind("error: ", 0) == 0 || line.rfind("run '", 0) == 0) << args << ": " << line;
      at = r.err.find('\n', at);
      at = at == std::string::npos ? r.err.size() : at + 1;
    }
  }
  // The worker prints its input errors the same way.
  const CommandRun worker = run_executable("gridfree-worker", "solve missing.json", dir);
  EXPECT_EQ(worker.exit_code, 2) << worker.err;
  EXPECT_EQ(worker.err.rfind("error: missing.json: ", 0), 0u) << worker.err;
  const CommandRun help = run_executable("gridfree", "help run", dir);
  EXPECT_NE(help.out.find("Usage: gridfree run"), std::string::npos) << help.out;
  const auto slurm = help.out.find("Slurm (--executor slurm only):");
  ASSERT_NE(slurm, std::string::npos) << help.out;
  EXPECT_GT(help.out.find("--partition"), slurm);
  EXPECT_LT(help.out.find("--jobs"), slurm);
}

}  // namespace
