// SPDX-License-Identifier: GPL-3.0-or-later
// An OpenFOAM study whose finest grid runs on 2 MPI ranks on the local pool
// (tests/support/openfoam_mpi_study.h: the cavity with a decomposeParDict
// and an Allrun that calls mpirun when @@cores@@ > 1; the cores rule gives
// the 20² grid 2 cores). Checked: only that grid's run folder holds
// processor0 and processor1, its log names its 2 cores, and its mean |U|²
// equals the serial run's (the same study without the rule) to 1e-8
// relative: every linear solve converges to 1e-10 (fvSolution, relTol 0),
// so decomposing changes the answer by about that, below the 9 significant
// digits the function object writes (measured: all 9 equal). The same
// study as multi-task Slurm arrays: tests/integration/slurm/slurm_cluster_test.cpp.
// OpenFOAM must be installed (scripts/install-deps.sh test installs it):
// without it this test fails, it does not skip.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "fake_worker.h"
#include "openfoam_mpi_study.h"
#include "openfoam_present.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace openfoam_mpi_test {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

const fs::path kMpiWorker = fs::path(GRIDFREE_BIN_DIR) / "gridfree-worker";

ts::CommandRun run_gridfree(const fs::path& dir, const std::string& args) {
  return ts::gridfree_in(dir, args, "GRIDFREE_WORKER=" + ts::shell_quote(kMpiWorker.string()));
}

// Run folders (<db>.runs/<2 hex>/<hash>/case) that hold processor1; sets
// *this_one when job `hash`'s does, with processor0 beside it.
int decomposed_run_folders(const fs::path& runs, const std::string& hash, bool* this_one) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(runs)) {
    if (!e.is_directory() || e.path().filename() != "processor1") continue;
    ++n;
    const fs::path case_dir = e.path().parent_path();
    if (case_dir.parent_path().filename() == hash && fs::is_directory(case_dir / "processor0"))
      *this_one = true;
  }
  return n;
}

TEST(OpenFoamMpi, TheFinestGridRunsOnTwoRanksAndGivesTheSerialAnswer) {
  ASSERT_TRUE(ts::openfoam_present()) << "OpenFOAM is not installed: run scripts/install-deps.sh test";
  const auto dir = ts::fresh_scratch_dir("external_openfoam_mpi", "local");
  const auto ranks = ts::write_openfoam_mpi_study(dir, "cavity_mpi", true);
  const auto serial = ts::write_openfoam_mpi_study(dir, "cavity_serial", false);

  const auto r = run_gridfree(dir, "run " + ranks.filename().string() + " --db mpi.sqlite -j 2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(ts::sqlite_int(dir / "mpi.sqlite", "SELECT COUNT(*) FROM results WHERE status = 'converged'"), 3);
  const std::string finest = "abs(delta_star - 0.1 / " + std::to_string(ts::kMpiFinestN) + ") < 1e-12";
  const std::string hash = ts::sqlite_query(dir / "mpi.sqlite", "SELECT job_hash FROM jobs WHERE " + finest);
  ASSERT_EQ(hash.size(), 64u) << hash;
  bool finest_decomposed = false;
  EXPECT_EQ(decomposed_run_folders(dir / "mpi.sqlite.runs", hash, &finest_decomposed), 1);
  EXPECT_TRUE(finest_decomposed);
  EXPECT_NE((r.out + r.err).find("2 core(s)"), std::string::npos) << r.out << r.err;

  const auto s = run_gridfree(dir, "run " + serial.filename().string() + " --db serial.sqlite -j 2");
  ASSERT_EQ(s.exit_code, 0) << s.out << s.err;
  bool unused = false;
  EXPECT_EQ(decomposed_run_folders(dir / "serial.sqlite.runs", hash, &unused), 0);
  const std::string value = "SELECT printf('%.17g', value) FROM v_results WHERE " + finest;
  const double on_two = std::stod(ts::sqlite_query(dir / "mpi.sqlite", value));
  const double on_one = std::stod(ts::sqlite_query(dir / "serial.sqlite", value));
  EXPECT_GT(on_one, 0);
  EXPECT_NEAR(on_two, on_one, 1e-8 * on_one);
}

}  // namespace openfoam_mpi_test
