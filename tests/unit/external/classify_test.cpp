// SPDX-License-Identifier: GPL-3.0-or-later
// classify_external: each rule on its own with the reason it gives, and the
// order (an earlier rule wins over a later one that also applies).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "external/classify.h"

namespace gridfree {
namespace {

// A run that converged: exit 0, one quantity settled, residual below tolerance.
ExternalSightings clean_run() {
  ExternalSightings s;
  s.exit = ExternalExit{0, std::nullopt};
  s.quantities.push_back({"ke", "post/ke.dat", 0.0616451980, 0.0616451979, ""});
  s.residual = ResidualSighting{"log.icoFoam", 3e-12, "", 1e-8};
  s.steady_tolerance = 1e-6;
  return s;
}

TEST(ExternalClassify, Converged) {
  const auto c = classify_external(clean_run());
  EXPECT_EQ(c.status, "converged");
  EXPECT_EQ(c.outcome, "converged");
  EXPECT_EQ(c.reason, "exit code 0, 1 quantity read, residual 3e-12 ≤ 1e-08");
}

TEST(ExternalClassify, CommandNotFoundOrNotExecutable) {
  auto s = clean_run();
  s.exit = ExternalExit{127, std::nullopt};
  s.stderr_tail = "sh: 1: blockMesh: not found";
  auto c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason, "command not found (exit code 127) (stderr: sh: 1: blockMesh: not found)");
  s.exit = ExternalExit{126, std::nullopt};
  s.failure = FailureSighting{"FOAM FATAL", "stdout.log", 3, "x"};  // rule 1 before rule 2
  c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason.rfind("command not executable (exit code 126)", 0), 0u) << c.reason;
}

TEST(ExternalClassify, FailurePatternBeforeExitCode) {
  auto s = clean_run();
  s.exit = ExternalExit{1, std::nullopt};
  s.failure = FailureSighting{"FOAM FATAL", "log.blockMesh", 12, "--> FOAM FATAL IO ERROR: | keyword N undefined"};
  const auto c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.outcome, "failed");
  EXPECT_EQ(c.reason,
            "failure pattern \"FOAM FATAL\" at line 12 of log.blockMesh: --> FOAM FATAL IO ERROR: | keyword N undefined");
}

// The failed command's stderr follows the pattern's line, unless that
// line is stderr's own (said once).
TEST(ExternalClassify, FailurePatternWithTheTailOfStderr) {
  auto s = clean_run();
  s.exit = ExternalExit{1, std::nullopt};
  s.stderr_tail = "mpirun: rank 0 exited | aborting";
  s.failure = FailureSighting{"FOAM FATAL", "log.blockMesh", 12, "--> FOAM FATAL ERROR: | cannot find file"};
  EXPECT_EQ(classify_external(s).reason,
            "failure pattern \"FOAM FATAL\" at line 12 of log.blockMesh: --> FOAM FATAL ERROR: | cannot find file "
            "(stderr: mpirun: rank 0 exited | aborting)");
  s.failure = FailureSighting{"FOAM FATAL", "stderr.log", 1, "--> FOAM FATAL ERROR: | cannot find file"};
  EXPECT_EQ(classify_external(s).reason,
            "failure pattern \"FOAM FATAL\" at line 1 of stderr.log: --> FOAM FATAL ERROR: | cannot find file");
}

TEST(ExternalClassify, FailurePatternEvenWithExitZero) {
  auto s = clean_run();
  s.failure = FailureSighting{"FOAM FATAL", "stdout.log", 2, "FOAM FATAL ERROR"};
  EXPECT_EQ(classify_external(s).status, "failed");
}

TEST(ExternalClassify, NonZeroExitOrSignal) {
  auto s = clean_run();
  s.exit = ExternalExit{3, std::nullopt};
  EXPECT_EQ(classify_external(s).reason, "exit code 3");
  s.exit = ExternalExit{std::nullopt, 11};
  s.stderr_tail = "Segmentation fault";
  const auto c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason, "killed by SIGSEGV (stderr: Segmentation fault)");
}

TEST(ExternalClassify, TheCommandsOwnVerdict) {
  auto s = clean_run();
  s.driver = DriverVerdict{"diverged", "CFL blew up"};
  auto c = classify_external(s);
  EXPECT_EQ(c.status, "diverged");
  EXPECT_EQ(c.reason, "the command's gridfree_result.json says diverged: CFL blew up");
  s.driver = DriverVerdict{"not_converged", ""};
  EXPECT_EQ(classify_external(s).status, "not_converged");
  s.driver = DriverVerdict{"converged", ""};  // then the usual rules
  EXPECT_EQ(classify_external(s).status, "converged");
}

TEST(ExternalClassify, MissingQuantityOrResidual) {
  auto s = clean_run();
  s.quantities[0].last.reset();
  s.quantities[0].problem = "no file matches post/*.dat in the case folder";
  auto c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason, "quantity ke missing: no file matches post/*.dat in the case folder");
  s = clean_run();
  s.residual->last.reset();
  s.residual->problem = "no line matches \"Ux\" in log.icoFoam";
  c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason, "residual missing: no line matches \"Ux\" in log.icoFoam");
}

TEST(ExternalClassify, MissingBeforeNan) {
  auto s = clean_run();
  s.quantities.push_back({"nan_one", "a.dat", std::numeric_limits<double>::quiet_NaN(), std::nullopt, ""});
  s.quantities.push_back({"gone", "b.dat", std::nullopt, std::nullopt, "no data row"});
  EXPECT_EQ(classify_external(s).status, "failed");
}

TEST(ExternalClassify, NanOrInfDiverged) {
  auto s = clean_run();
  s.quantities[0].last = std::numeric_limits<double>::quiet_NaN();
  auto c = classify_external(s);
  EXPECT_EQ(c.status, "diverged");
  EXPECT_EQ(c.outcome, "diverged");
  EXPECT_EQ(c.reason, "quantity ke is nan in post/ke.dat");
  s = clean_run();
  s.residual->last = std::numeric_limits<double>::infinity();
  c = classify_external(s);
  EXPECT_EQ(c.status, "diverged");
  EXPECT_EQ(c.reason, "residual is inf in log.icoFoam");
}

TEST(ExternalClassify, ResidualAboveTolerance) {
  auto s = clean_run();
  s.residual->last = 2e-5;
  s.quantities[0].previous = 0.5;  // also still changing: the residual rule comes first
  const auto c = classify_external(s);
  EXPECT_EQ(c.status, "not_converged");
  EXPECT_EQ(c.outcome, "stalled");
  EXPECT_EQ(c.reason, "residual 2e-05 above the tolerance 1e-08 (last value in log.icoFoam)");
}

TEST(ExternalClassify, StillChanging) {
  auto s = clean_run();
  s.quantities[0].last = 1.0;
  s.quantities[0].previous = 0.9988;
  const auto c = classify_external(s);
  EXPECT_EQ(c.status, "not_converged");
  EXPECT_EQ(c.outcome, "iteration_cap");
  EXPECT_EQ(c.reason, "quantity ke still changing: 0.0012 between the last two records of post/ke.dat (steady_tolerance 1e-06)");
  s.steady_tolerance.reset();  // not asked for: not checked
  EXPECT_EQ(classify_external(s).status, "converged");
  s.steady_tolerance = 1e-6;
  s.quantities[0].previous.reset();  // one record: nothing to compare
  EXPECT_EQ(classify_external(s).status, "converged");
}

TEST(ExternalClassify, RelativeChange) {
  EXPECT_DOUBLE_EQ(relative_change(1.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(relative_change(-2.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(relative_change(0.0, 0.0), 0.0);
}

TEST(ExternalClassify, NoRecordOfTheEndFailsWhateverTheFilesSay) {
  auto s = clean_run();
  s.exit.reset();
  const auto c = classify_external(s);
  EXPECT_EQ(c.status, "failed");
  EXPECT_EQ(c.reason, "no record of how the command ended (case/.gridfree_exit): the run did not finish");
}

}  // namespace
}  // namespace gridfree
