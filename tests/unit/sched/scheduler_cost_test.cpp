// SPDX-License-Identifier: GPL-3.0-or-later
// The store work of one job through the scheduler loop — claim (budget
// rule's candidates + claim), record, finish the series it completes,
// refresh the study's status — does not grow with the study: counted in
// SQLite virtual-machine steps (sqlite3_stmt_status VM_STEP, summed over
// every statement by a profile trace), which is deterministic, unlike a
// time. A study 40 times larger may cost at most 1.5 times the steps per
// job (the B-tree depth grows a little; a scan would grow 40 times).
#include <gtest/gtest.h>

#include <sqlite3.h>

#include "sched/budget_claim.h"
#include "sched/series_finish.h"
#include "store/owner.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// n_series series of 18 grids, grid g of each with its own cells.
std::pair<Study, ExpandedStudy> ensemble_study(int n_series) {
  Study s;
  s.name = "cost";
  s.definition = {{"name", "cost"}};
  ExpandedStudy ex;
  for (int i = 0; i < n_series; ++i) {
    ex.series.push_back(SeriesKey{"case" + std::to_string(i), "superbee", 6, "bvk", "diffusion"});
    for (int g = 0; g < 18; ++g) {
      StudyJob j;
      j.series = static_cast<std::size_t>(i);
      j.grid = static_cast<std::size_t>(g);
      j.delta_star = 3.0 / (1 + 0.2 * g);
      j.cells = {10 + g, 10 + g, 4};
      j.doc = {{"series", i}, {"grid", g}};
      j.hash = "c" + std::to_string(i) + "g" + std::to_string(g);
      ex.jobs.push_back(j);
    }
  }
  return {s, ex};
}

int profile_steps(unsigned type, void* ctx, void* stmt, void*) {
  if (type == SQLITE_TRACE_PROFILE)
    *static_cast<long long*>(ctx) += sqlite3_stmt_status(static_cast<sqlite3_stmt*>(stmt), SQLITE_STMTSTATUS_VM_STEP, 1);
  return 0;
}

// Mean VM steps per job of the loop over 5 series of 18 jobs in a study of
// n_series series whose other series are done already: the same work in a
// small and in a large study. The last job is left out: it ends the study,
// and the study's final status counts its jobs once.
double steps_per_job(int n_series) {
  const fs::path dir = test_support::fresh_scratch_dir("sched_unit", "cost" + std::to_string(n_series));
  Store store(dir / "db.sqlite");
  const auto [s, ex] = ensemble_study(n_series);
  const long long study = store.submit(s, ex).study_id;
  store.db().exec(
      "UPDATE jobs SET status = 'done' WHERE id IN (SELECT sj.job_id FROM study_jobs sj "
      "JOIN series se ON se.id = sj.series_id WHERE se.position >= 5)");
  store.db().exec("UPDATE series SET status = 'done' WHERE position >= 5");
  const std::string owner = this_process_owner();
  long long steps = 0;
  sqlite3_trace_v2(store.db().handle(), SQLITE_TRACE_PROFILE, profile_steps, &steps);
  HeadReservation reservation;
  const int jobs = 5 * 18 - 1;
  int finished = 0;
  for (int i = 0; i < jobs; ++i) {
    const auto job = claim_within_budget(store, study, owner, {}, {0, 1, 1}, reservation);
    if (!job) {
      ADD_FAILURE() << "nothing to claim at job " << i;
      break;
    }
    ResultRow r;
    r.status = "converged";
    r.dp_star = 1159 + job->spec["grid"].get<double>();
    store.record_result(job->job_id, owner, r);
    finished += finish_series_of_job(store, study, job->job_id, false);
  }
  sqlite3_trace_v2(store.db().handle(), 0, nullptr, nullptr);
  EXPECT_EQ(finished, 4);  // the largest grids go first: the series end together, at the end
  return static_cast<double>(steps) / jobs;
}

TEST(SchedulerCost, StoreStepsPerJobDoNotGrowWithTheStudy) {
  const double small = steps_per_job(5);    // 90 jobs
  const double large = steps_per_job(200);  // 3 600 jobs
  EXPECT_GT(small, 0);
  EXPECT_LE(large, 1.5 * small) << "VM steps per job: " << small << " at 90 jobs, " << large << " at 3600";
  RecordProperty("steps_per_job_90", std::to_string(small));
  RecordProperty("steps_per_job_3600", std::to_string(large));
}

// Mean VM steps of a claim (and its record) while every series of the
// study is still queued — the state of an ensemble run's main phase, where
// each grid size has one queued job per series: 36 claims, the two largest
// sizes of every series in the small study, in the large one the largest
// size of 36 of its series.
double claim_steps_all_queued(int n_series) {
  const fs::path dir = test_support::fresh_scratch_dir("sched_unit", "queued" + std::to_string(n_series));
  Store store(dir / "db.sqlite");
  const auto [s, ex] = ensemble_study(n_series);
  const long long study = store.submit(s, ex).study_id;
  const std::string owner = this_process_owner();
  long long steps = 0;
  sqlite3_trace_v2(store.db().handle(), SQLITE_TRACE_PROFILE, profile_steps, &steps);
  HeadReservation reservation;
  const int claims = 36;
  for (int i = 0; i < claims; ++i) {
    const auto job = claim_within_budget(store, study, owner, {}, {0, 1, 1}, reservation);
    if (!job) {
      ADD_FAILURE() << "nothing to claim at claim " << i;
      break;
    }
    ResultRow r;
    r.status = "converged";
    r.dp_star = 1159;
    store.record_result(job->job_id, owner, r);
  }
  sqlite3_trace_v2(store.db().handle(), 0, nullptr, nullptr);
  return static_cast<double>(steps) / claims;
}

// The claim's walk over the queued grid sizes must seek from one size to
// the next, not step over every queued job of a size (a row-value range
// (nx, ny, nz) > (a, b, c) seeks on nx alone: 8.8x the steps here (5 453 → 48 100), and
// about 5 ms of orchestrator CPU per claim at 50 004 jobs).
TEST(SchedulerCost, ClaimStepsDoNotGrowWithTheQueuedJobsOfASize) {
  const double small = claim_steps_all_queued(18);   // 324 jobs, 18 per size
  const double large = claim_steps_all_queued(200);  // 3 600 jobs, 200 per size
  EXPECT_GT(small, 0);
  RecordProperty("claim_steps_18", std::to_string(small));
  RecordProperty("claim_steps_200", std::to_string(large));
  EXPECT_LE(large, 1.5 * small) << "VM steps per claim: " << small << " at 18 series, " << large << " at 200";
}

TEST(SchedulerCost, TheFinishedJobsSeriesAreFinished) {
  const fs::path dir = test_support::fresh_scratch_dir("sched_unit", "finish");
  Store store(dir / "db.sqlite");
  const auto [s, ex] = ensemble_study(3);
  const long long study = store.submit(s, ex).study_id;
  const std::string owner = this_process_owner();
  HeadReservation reservation;
  int finished = 0;
  for (int i = 0; i < 18 * 3; ++i) {
    const auto job = claim_within_budget(store, study, owner, {}, {0, 1, 1}, reservation);
    ASSERT_TRUE(job);
    ResultRow r;
    r.status = "converged";
    r.dp_star = 1159 + job->spec["grid"].get<double>();
    store.record_result(job->job_id, owner, r);
    finished += finish_series_of_job(store, study, job->job_id, false);
    if (i < 18 * 3 - 3) {  // largest grids first: the series end last
      EXPECT_EQ(finished, 0) << i;
    }
  }
  EXPECT_EQ(finished, 3);
  EXPECT_EQ(store.refresh_study_status(study), "done");
  for (const auto& se : store.series_of_study(study)) EXPECT_EQ(se.status, "done");
}

}  // namespace
}  // namespace gridfree
