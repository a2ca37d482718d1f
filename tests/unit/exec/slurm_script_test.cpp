// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm array scripts (exec/slurm_script.h): run by /bin/sh here with a fake
// worker that records its arguments, so the quoting is checked by a shell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "exec/slurm_script.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

TEST(SlurmScript, EachTaskRunsTheWorkerInItsOwnFolderWhateverTheName) {
  const auto dir = test_support::fresh_scratch_dir("slurm_script", "tasks");
  const fs::path worker = dir / "fake worker's.sh";
  std::ofstream(worker) << "#!/bin/sh\nfor a; do echo \"$a\"; done > \"$(dirname \"$2\")/args\"\nexit 3\n";
  fs::permissions(worker, fs::perms::owner_all);
  SlurmArray a;
  a.run_dirs = {dir / "run one", dir / "it's two"};
  a.threads = 2;
  a.bed_cache = dir / "beds of 'all'";
  for (const auto& d : a.run_dirs) fs::create_directories(d);
  std::ofstream(dir / "job.sh") << array_script(worker, a, {"export GF_SETUP_RAN=yes"});
  for (int task = 0; task < 2; ++task) {
    const std::string cmd = "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " sh '" + (dir / "job.sh").string() + "'";
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 3);  // the worker's exit code is the task's
    std::ifstream code(a.run_dirs[task] / "exit_code");
    int c = -1;
    code >> c;
    EXPECT_EQ(c, 3);
    std::ifstream args(a.run_dirs[task] / "args");
    std::string first, job;
    std::getline(args, first);
    std::getline(args, job);
    EXPECT_EQ(first, "solve");
    EXPECT_EQ(job, (a.run_dirs[task] / "job.json").string());
    std::string word, bed_cache;
    while (std::getline(args, word) && word != "--bed-cache") {
    }
    std::getline(args, bed_cache);
    EXPECT_EQ(bed_cache, a.bed_cache.string()) << "every task shares the database's bed cache";
  }
  EXPECT_NE(std::system(("SLURM_ARRAY_TASK_ID=7 sh '" + (dir / "job.sh").string() + "' 2>/dev/null").c_str()), 0);
}

// Slurm's SIGTERM goes to the batch shell (--signal=B:TERM@...): the script
// passes it to the worker and records the worker's own exit code (130 after
// a checkpoint), not the shell's interrupted wait.
TEST(SlurmScript, TermToTheShellReachesTheWorkerAndItsExitCodeIsKept) {
  const auto dir = test_support::fresh_scratch_dir("slurm_script", "term");
  const fs::path worker = dir / "worker.sh";
  std::ofstream(worker) << "#!/bin/sh\ntrap 'sleep 0.3; exit 130' TERM\n: > \"$(dirname \"$2\")/started\"\n"
                           "i=0; while [ $i -lt 200 ]; do sleep 0.05; i=$((i+1)); done\nexit 0\n";
  fs::permissions(worker, fs::perms::owner_all);
  SlurmArray a;
  a.run_dirs = {dir / "run"};
  fs::create_directories(a.run_dirs[0]);
  std::ofstream(dir / "job.sh") << array_script(worker, a, {});
  const std::string cmd = "cd '" + dir.string() + "' && (SLURM_ARRAY_TASK_ID=0 sh job.sh & echo $! > shell.pid; wait) ; "
                          "true";
  const std::string driver = "(" + cmd + ") & i=0; while [ ! -e '" + (a.run_dirs[0] / "started").string() +
                             "' ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i+1)); done; kill -TERM $(cat '" +
                             (dir / "shell.pid").string() + "'); wait";
  ASSERT_EQ(std::system(driver.c_str()), 0);
  std::ifstream code(a.run_dirs[0] / "exit_code");
  int c = -1;
  code >> c;
  EXPECT_EQ(c, 130);
}

TEST(SlurmScript, SbatchGetsEverySettingAsItsOwnWord) {
  SlurmArray a;
  a.name = "study/series d*=2.5";
  a.run_dirs = {"/x", "/y", "/z"};
  a.cpus = 4;
  a.time_minutes = 16;
  a.mem_mb = 512;
  a.throttle = 8;
  SlurmSettings s;
  s.partition = "p";
  s.account = "acc";
  s.qos = "q";
  s.constraint = "c";
  s.sbatch_args = {"--exclusive"};
  const auto c = sbatch_command(a, s, "/runs dir/s.sbatch", "/runs dir/slurm");
  const std::vector<std::string> want = {"sbatch", "--parsable", "--job-name=study/series_d*=2.5",
                                         "--output=/runs dir/slurm/%A_%a.out", "--cpus-per-task=4",
                                         "--array=0-2%8", "--time=16", "--mem=512M", "--signal=B:TERM@120",
                                         "--no-requeue", "--partition=p",
                                         "--account=acc", "--qos=q", "--constraint=c", "--exclusive",
                                         "/runs dir/s.sbatch"};
  EXPECT_EQ(c, want);
}

// The log line of a submission round names each limit's source and value.
TEST(SlurmScript, TheLimitsNoteSaysWhereTimeAndMemoryCameFrom) {
  SlurmArray from_env;
  from_env.time_from = "from SBATCH_TIMELIMIT";
  from_env.time_shown = "00:07:00";
  from_env.mem_mb = 4096;
  from_env.mem_from = "computed from the cost model x 3";
  SlurmArray bigger = from_env;
  bigger.mem_mb = 8192;
  EXPECT_EQ(limits_note({from_env, bigger}),
            "time limit 00:07:00 from SBATCH_TIMELIMIT; memory 4096M-8192M computed from the cost model x 3");
  SlurmArray given;
  given.time_minutes = 90;
  given.time_from = "from the settings (--time / time_minutes)";
  EXPECT_EQ(limits_note({given}),
            "time limit 01:30:00 from the settings (--time / time_minutes); memory the cluster's default");
  EXPECT_EQ(slurm_time_text(1450.5), "24:10:30");
}

// A cores rule (study/job_cores.h): each array asks for its jobs' own cores,
// an external code's as MPI tasks, the worker's as CPUs of one task; jobs
// of different cores never share an array.
TEST(SlurmScript, CoresRuleGivesEachArrayItsTasksOrCpus) {
  JobLaunch external;
  external.own_estimate = true;
  external.cores_are_tasks = true;
  external.threads = 4;
  external.cores = 4;
  SlurmArray mpi;
  mpi.run_dirs = {"/a"};
  apply_job_cores(mpi, external);
  EXPECT_EQ(mpi.tasks, 4);
  EXPECT_EQ(mpi.cpus, 1);
  EXPECT_EQ(mpi.threads, 4);
  const auto c = sbatch_command(mpi, SlurmSettings{}, "/s.sbatch", "/log");
  EXPECT_NE(std::find(c.begin(), c.end(), "--ntasks=4"), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), "--cpus-per-task=1"), c.end());

  JobLaunch worker;
  worker.threads = 2;
  worker.cores = 2;
  SlurmArray omp;
  omp.run_dirs = {"/b"};
  apply_job_cores(omp, worker);
  EXPECT_EQ(omp.tasks, 1);
  EXPECT_EQ(omp.cpus, 2);
  const auto w = sbatch_command(omp, SlurmSettings{}, "/s.sbatch", "/log");
  EXPECT_NE(std::find(w.begin(), w.end(), "--cpus-per-task=2"), w.end());
  EXPECT_EQ(std::find_if(w.begin(), w.end(), [](const std::string& x) { return x.rfind("--ntasks", 0) == 0; }),
            w.end());

  // Without a rule the shape stays (the settings' --cpus-per-task).
  JobLaunch plain;
  plain.threads = 1;
  SlurmArray fixed;
  fixed.cpus = 8;
  apply_job_cores(fixed, plain);
  EXPECT_EQ(fixed.cpus, 8);
  EXPECT_EQ(fixed.tasks, 1);

  // Grouping: one array per core count.
  JobLaunch one = external;
  one.threads = one.cores = 1;
  SlurmArray mpi1;
  apply_job_cores(mpi1, one);
  EXPECT_FALSE(same_array_shape(mpi, mpi1));
  SlurmArray mpi4b;
  apply_job_cores(mpi4b, external);
  EXPECT_TRUE(same_array_shape(mpi, mpi4b));
  EXPECT_FALSE(same_array_shape(mpi, omp));
}

}  // namespace
}  // namespace gridfree
