// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run --executor slurm` against fake Slurm commands on a temporary
// PATH (docs/ORCHESTRATOR.md "Slurm"): a missing command is refused before
// the database exists (exit 2); sbatch refusing a submission requeues the
// jobs without spending an attempt (exit 2), and the same command then
// finishes once sbatch works; the user's SBATCH_TIMELIMIT wins over the
// computed --time and the log says so; sbatch words gridfree sets itself are
// refused in their short forms; a local run ignores a valid slurm block.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace slurm_cli {
namespace {

namespace fs = std::filesystem;
using gridfree::test_support::kFakeWorker;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;

using Run = gridfree::test_support::MergedRun;

// gridfree in `dir` with the fake worker, PATH = `path`, more variables in `env`.
Run slurm_gridfree(const fs::path& dir, const std::string& args, const std::string& path,
                   const std::string& env = "") {
  return gridfree::test_support::run_merged("cd " + shell_quote(dir.string()) + " && env PATH=" +
                                            shell_quote(path) + " GRIDFREE_WORKER=" +
                                            shell_quote(kFakeWorker.string()) + " " + env + " " +
                                            shell_quote(kGridfreeExe.string()) + " " + args);
}

// Fake sbatch/squeue/scancel in dir/bin. sbatch logs its arguments to
// dir/sbatch_args; with dir/refuse present it fails as for a bad partition,
// else it runs every task of the array at once and prints an id. squeue
// lists nothing (the tasks have ended; their exit_code files tell).
fs::path fake_slurm_bin(const fs::path& dir, bool with_sbatch = true) {
  const auto bin = dir / "bin";
  fs::create_directories(bin);
  auto script = [&](const std::string& name, const std::string& body) {
    std::ofstream(bin / name) << "#!/bin/sh\n" << body;
    fs::permissions(bin / name, fs::perms::owner_all);
  };
  if (with_sbatch)
    script("sbatch", "echo \"$@\" >> " + shell_quote((dir / "sbatch_args").string()) + "\n" +
                         "[ -e " + shell_quote((dir / "refuse").string()) +
                         " ] && { echo 'sbatch: error: invalid partition name specified' >&2; exit 1; }\n"
                         "last=0; for a; do case $a in --array=0-*) last=${a#--array=0-}; last=${last%%%*} ;; esac; "
                         "script=$a; done\n"
                         "i=0; while [ $i -le $last ]; do SLURM_ARRAY_TASK_ID=$i sh \"$script\" >/dev/null 2>&1; "
                         "i=$((i + 1)); done\n"
                         "echo \"7$i;cluster\"\n");
  script("squeue", "exit 0\n");
  script("scancel", "exit 0\n");
  return bin;
}

std::string system_path() {
  const char* p = std::getenv("PATH");
  return p == nullptr ? "/usr/bin:/bin" : p;
}

fs::path scratch(const std::string& name) { return gridfree::test_support::fresh_scratch_dir("slurm_cli", name); }

TEST(SlurmCli, AMissingSbatchIsRefusedBeforeTheDatabaseExists) {
  const auto dir = scratch("missing");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  const auto bin = fake_slurm_bin(dir, false);  // squeue and scancel only
  const auto r = slurm_gridfree(dir, "run " + shell_quote(study.string()) + " --executor slurm --db g.sqlite",
                                bin.string());
  EXPECT_EQ(r.code, 2) << r.text;
  EXPECT_NE(r.text.find("'sbatch'"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("PATH=" + bin.string()), std::string::npos) << r.text;
  EXPECT_FALSE(fs::exists(dir / "g.sqlite"));
  EXPECT_FALSE(fs::exists(dir / "g.sqlite.runs"));
}

// sbatch refusing for good: exit 2, every job queued with no attempt
// spent and no result; once sbatch works, the same command finishes.
TEST(SlurmCli, ARefusedSubmissionSpendsNoAttemptAndTheNextRunFinishes) {
  const auto dir = scratch("refused");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  const auto bin = fake_slurm_bin(dir);
  const std::string path = bin.string() + ":" + system_path();
  const std::string run = "run " + shell_quote(study.string()) + " --executor slurm --db g.sqlite";
  std::ofstream(dir / "refuse") << "";
  auto r = slurm_gridfree(dir, run, path);
  EXPECT_EQ(r.code, 2) << r.text;
  EXPECT_NE(r.text.find("invalid partition name specified"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("refused command: sbatch --parsable"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("no attempt or core-hour spent"), std::string::npos) << r.text;
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT status, attempts, COUNT(*) FROM jobs GROUP BY status, attempts"), "queued|0|3");
  // The jobs keep sbatch's reason, not only "interrupted".
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE error LIKE '%invalid partition name specified%'"), "3");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM results"), "0");
  fs::remove(dir / "refuse");
  r = slurm_gridfree(dir, run, path);
  EXPECT_EQ(r.code, 0) << r.text;
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM results WHERE status = 'converged'"), "3");
}

// SBATCH_TIMELIMIT / SBATCH_MEM_PER_NODE set: no --time/--mem of gridfree's
// own (sbatch would let them override the environment); the log says which
// applied. Without them the computed values are passed.
TEST(SlurmCli, TheUsersSbatchEnvironmentWinsAndTheLogSaysSo) {
  const auto dir = scratch("env");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  const auto bin = fake_slurm_bin(dir);
  const std::string path = bin.string() + ":" + system_path();
  auto r = slurm_gridfree(dir, "run " + shell_quote(study.string()) + " --executor slurm --db g.sqlite", path,
                          "SBATCH_TIMELIMIT=7 SBATCH_MEM_PER_NODE=500M");
  EXPECT_EQ(r.code, 0) << r.text;
  std::ifstream in(dir / "sbatch_args");
  std::string args((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(args.find("--time"), std::string::npos) << args;
  EXPECT_EQ(args.find("--mem"), std::string::npos) << args;
  EXPECT_NE(r.text.find("time limit 00:07:00 from SBATCH_TIMELIMIT; memory 500M from SBATCH_MEM_PER_NODE"),
            std::string::npos)
      << r.text;
  // A flag wins over the environment.
  fs::remove(dir / "sbatch_args");
  r = slurm_gridfree(dir, "run " + shell_quote(study.string()) + " --executor slurm --db h.sqlite --time 9", path,
                     "SBATCH_TIMELIMIT=7");
  EXPECT_EQ(r.code, 0) << r.text;
  std::ifstream in2(dir / "sbatch_args");
  args.assign((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  EXPECT_NE(args.find("--time=9 "), std::string::npos) << args;
  EXPECT_NE(args.find("--mem="), std::string::npos) << args;  // computed: no memory setting anywhere
  EXPECT_NE(r.text.find("memory "), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("computed from the cost model x 3"), std::string::npos) << r.text;
}

TEST(SlurmCli, SbatchWordsGridfreeSetsItselfAreRefusedInTheirShortForms) {
  const auto dir = scratch("short");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  const auto bin = fake_slurm_bin(dir);
  const std::string path = bin.string() + ":" + system_path();
  for (const std::string arg : {"-o", "-ofile", "-e", "--error=x", "-J", "--out=x"}) {
    const auto r = slurm_gridfree(dir,
                                  "run " + shell_quote(study.string()) + " --executor slurm --db g.sqlite " +
                                      shell_quote("--sbatch-arg=" + arg),
                                  path);
    EXPECT_EQ(r.code, 2) << arg << "\n" << r.text;
    EXPECT_NE(r.text.find("--sbatch-arg"), std::string::npos) << r.text;
    EXPECT_NE(r.text.find("'" + arg + "'"), std::string::npos) << r.text;
  }
  EXPECT_FALSE(fs::exists(dir / "g.sqlite"));
  EXPECT_FALSE(fs::exists(dir / "sbatch_args"));
}

// validate refuses a mistyped slurm key with the nearest name; a local run
// ignores a valid slurm block (it applies to --executor slurm).
TEST(SlurmCli, ValidateChecksTheSlurmBlockAndALocalRunIgnoresIt) {
  const auto dir = scratch("block");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  auto doc = nlohmann::json::parse(std::ifstream(study));
  doc["slurm"] = {{"partiton", "debug"}};
  std::ofstream(dir / "typo.json") << doc.dump(2);
  auto r = slurm_gridfree(dir, "validate typo.json", system_path());
  EXPECT_EQ(r.code, 2) << r.text;
  EXPECT_NE(r.text.find("/slurm/partiton"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("did you mean 'partition'?"), std::string::npos) << r.text;
  doc["slurm"] = {{"partition", "debug"}, {"time_minutes", 10}, {"sbatch_args", {"--exclusive"}}};
  std::ofstream(dir / "valid.json") << doc.dump(2);
  r = slurm_gridfree(dir, "validate valid.json", system_path());
  EXPECT_EQ(r.code, 0) << r.text;
  r = slurm_gridfree(dir, "run valid.json --db g.sqlite -j 1", system_path());
  EXPECT_EQ(r.code, 0) << r.text;
  EXPECT_NE(r.text.find("ignores them"), std::string::npos) << r.text;
}

}  // namespace
}  // namespace slurm_cli
