// SPDX-License-Identifier: GPL-3.0-or-later
// The not_converged reason's note on drag-update checks (flow/outer_status.h):
// the trial's job quoted residuals all below tolerance because they were the
// last iteration's, while the steady criterion is checked only on
// drag-update iterations; the note names the check and what failed.
#include "flow/outer_status.h"

#include <gtest/gtest.h>

namespace gridfree {
namespace {

TEST(OuterStatus, SteadyCheckNoteNamesTheFailedCriterion) {
  // Checked every iteration: nothing to add.
  EXPECT_EQ(steady_check_note(SteadyCheck{29, 2e-5, 1e-6, 1e-8}, 1, 10, 1e-5), "");
  EXPECT_EQ(steady_check_note(SteadyCheck{29, 2.1e-5, 9.97e-6, 3.51e-8}, 4, 10, 1e-5),
            "; the steady criterion is checked on drag-update iterations (every 4th); the last check, at "
            "iteration 29, failed on the continuity residual 2.1e-05 ≥ 1e-05");
  EXPECT_EQ(steady_check_note(SteadyCheck{5, 2e-5, 3e-5, 4e-5}, 4, 10, 1e-5),
            "; the steady criterion is checked on drag-update iterations (every 4th); the last check, at "
            "iteration 5, failed on the minimum of 10 iterations, the continuity residual 2e-05 ≥ 1e-05, the "
            "momentum residual 3e-05 ≥ 1e-05 and the relative change of the quantity of interest 4e-05 ≥ 1e-05");
  EXPECT_EQ(steady_check_note(std::nullopt, 2, 10, 1e-5),
            "; the steady criterion is checked on drag-update iterations (every 2nd); none was checked");
}

TEST(OuterStatus, NotConvergedReasonPlusNote) {
  SimpleOutcome out;
  out.continuity = 1.49e-6;
  out.momentum = 9.97e-6;
  out.qoi_change = 3.51e-8;
  const std::string reason = not_converged_reason("30 iterations", out, 1e-5) +
                             steady_check_note(SteadyCheck{29, 1.2e-5, 9e-6, 2e-8}, 4, 10, 1e-5);
  EXPECT_NE(reason.find("not converged after 30 iterations: continuity residual 1.49e-06"), std::string::npos);
  EXPECT_NE(reason.find("failed on the continuity residual 1.2e-05 ≥ 1e-05"), std::string::npos) << reason;
}

}  // namespace
}  // namespace gridfree
