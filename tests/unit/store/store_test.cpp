// SPDX-License-Identifier: GPL-3.0-or-later
// The SQLite store: schema of docs/INTERFACE.md §5, submit/resume/reuse, the job
// state machine (claim, retry, release, stale requeue), atomic claims from
// two connections, series completion and integrity.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <thread>

#include "core/input_error.h"
#include "store/owner.h"
#include "store/schema.h"
#include "store/store.h"
#include "scratch_dir.h"
#include "store_queries.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

using test_support::converged;
using test_support::scalar;
using test_support::text;

// A study of `series` series × `grids` grids with synthetic job documents;
// `tag` makes its jobs distinct from another study's (or not, when equal).
std::pair<Study, ExpandedStudy> make_study(const std::string& name, int series, int grids, const std::string& tag) {
  Study s;
  s.name = name;
  s.definition = {{"name", name}, {"tag", tag}, {"series", series}, {"grids", grids}};
  ExpandedStudy ex;
  for (int i = 0; i < series; ++i) {
    ex.series.push_back(SeriesKey{"PC1", i == 0 ? "superbee" : "fou", 6.0 + i, "bvk", "diffusion"});
    for (int g = 0; g < grids; ++g) {
      StudyJob j;
      j.series = static_cast<std::size_t>(i);
      j.grid = static_cast<std::size_t>(g);
      j.cells = {10 + g, 20 + g, 5};
      j.delta_star = 3.0 - 0.5 * g;
      j.doc = {{"series", i}, {"grid", g}, {"tag", tag}};
      j.hash = tag + "-" + std::to_string(i) + "-" + std::to_string(g);
      ex.jobs.push_back(j);
    }
  }
  return {s, ex};
}

TEST(Store, SchemaHasTheContractTablesViewAndPragmas) {
  Store store(test_support::fresh_db_path("store_test", "schema"));
  EXPECT_EQ(schema_version(store.db()), kSchemaVersion);
  EXPECT_EQ(text(store, "PRAGMA journal_mode"), "wal");
  EXPECT_EQ(scalar(store, "PRAGMA foreign_keys"), 1);
  for (const char* table : {"studies", "jobs", "study_jobs", "results", "series", "extrapolations", "uncertainties"})
    EXPECT_EQ(scalar(store, std::string("SELECT COUNT(*) FROM sqlite_master WHERE type='table' AND name='") + table + "'"), 1)
        << table;
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM sqlite_master WHERE type='view' AND name='v_results'"), 1);
  // The contract's columns, by name.
  auto cols = [&](const std::string& table) {
    std::set<std::string> out;
    auto st = store.db().prepare("SELECT name FROM pragma_table_info('" + table + "')");
    while (st.step()) out.insert(st.as_text(0));
    return out;
  };
  for (const char* c : {"id", "name", "definition_json", "status", "submitted_at", "finished_at"})
    EXPECT_TRUE(cols("studies").count(c)) << c;
  for (const char* c : {"id", "job_hash", "spec_json", "status", "attempts", "started_at", "finished_at", "error"})
    EXPECT_TRUE(cols("jobs").count(c)) << c;
  for (const char* c : {"study_id", "job_id", "series_id"}) EXPECT_TRUE(cols("study_jobs").count(c)) << c;
  for (const char* c : {"job_id", "status", "dp_star", "delta_star", "nx", "ny", "nz", "iterations", "wall_s", "cpu_s",
                        "peak_rss_mb", "result_json"})
    EXPECT_TRUE(cols("results").count(c)) << c;
  for (const char* c : {"id", "study_id", "case_name", "convection", "fwhm_dp", "drag", "status"})
    EXPECT_TRUE(cols("series").count(c)) << c;
  for (const char* c : {"series_id", "method", "f0", "p", "c", "c1", "c2", "sigma_re", "data_range", "fs", "chosen"})
    EXPECT_TRUE(cols("extrapolations").count(c)) << c;
  for (const char* c : {"series_id", "job_id", "delta_star", "f", "u", "rde"})
    EXPECT_TRUE(cols("uncertainties").count(c)) << c;
}

TEST(Store, ReopeningMigratesNothingAndKeepsData) {
  const auto db = test_support::fresh_db_path("store_test", "reopen");
  {
    Store store(db);
    auto [s, ex] = make_study("a", 1, 2, "t");
    store.submit(s, ex);
  }
  Store again(db, false);
  EXPECT_EQ(scalar(again, "SELECT COUNT(*) FROM jobs"), 2);
}

TEST(Store, ACoverageCheckIsStoredWithItsSeries) {
  Store store(test_support::fresh_db_path("store_test", "coverage"));
  auto [s, ex] = make_study("a", 2, 3, "t");
  const long long study = store.submit(s, ex).study_id;
  const auto series = store.series_of_study(study);
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].coverage_json, "");  // none until the series finishes
  store.store_coverage(series[1].id, R"({"status":"checked","judged":3})");
  const auto again = store.series_of_study(study);
  EXPECT_EQ(again[0].coverage_json, "");
  EXPECT_EQ(again[1].coverage_json, R"({"status":"checked","judged":3})");
}

TEST(Store, SubmitInsertsEverythingAndResubmitIsANoOp) {
  Store store(test_support::fresh_db_path("store_test", "submit"));
  auto [s, ex] = make_study("a", 2, 3, "t");
  const auto first = store.submit(s, ex);
  EXPECT_TRUE(first.created);
  EXPECT_EQ(first.jobs_new, 6u);
  auto again = s;
  again.definition = nlohmann::json::parse(R"({"grids": 3.0, "series": 2, "tag": "t", "name": "a"})");  // same value
  const auto second = store.submit(again, ex);
  EXPECT_FALSE(second.created);
  EXPECT_EQ(second.study_id, first.study_id);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 6);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM study_jobs"), 6);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM series"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM v_results"), 6);

  auto changed = s;
  changed.definition["tag"] = "other";
  EXPECT_THROW(store.submit(changed, ex), InputError);
}

TEST(Store, JobsAlreadyDoneInAnotherStudyAreReusedNotRerun) {
  Store store(test_support::fresh_db_path("store_test", "reuse"));
  auto [a, exa] = make_study("a", 1, 2, "shared");
  const auto sa = store.submit(a, exa);
  const std::string me = this_process_owner();
  while (auto job = store.claim_next(sa.study_id, me)) store.record_result(job->job_id, me, converged(1159, 1));
  auto [b, exb] = make_study("b", 1, 2, "shared");
  b.definition["name"] = "b";
  const auto sb = store.submit(b, exb);
  EXPECT_EQ(sb.jobs_new, 0u);
  EXPECT_EQ(sb.jobs_reused, 2u);
  EXPECT_FALSE(store.claim_next(sb.study_id, me).has_value());
  EXPECT_EQ(store.series_ready(sb.study_id).size(), 1u);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 2);
}

TEST(Store, ClaimMarksRunningAndCountsAttempts) {
  Store store(test_support::fresh_db_path("store_test", "claim"));
  auto [s, ex] = make_study("a", 1, 2, "t");
  const auto sub = store.submit(s, ex);
  const auto job = store.claim_next(sub.study_id, "me");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->attempts, 1);
  EXPECT_EQ(text(store, "SELECT status FROM jobs WHERE id = " + std::to_string(job->job_id)), "running");
  EXPECT_EQ(text(store, "SELECT owner FROM jobs WHERE id = " + std::to_string(job->job_id)), "me");
  EXPECT_EQ(text(store, "SELECT status FROM studies"), "running");
  // Finest grid first within a series (largest cell count).
  EXPECT_EQ(job->cells[0], 11);
}

TEST(Store, TwoConnectionsNeverClaimTheSameJob) {
  const auto db = test_support::fresh_db_path("store_test", "atomic");
  constexpr int kJobs = 40;
  {
    Store store(db);
    auto [s, ex] = make_study("a", 4, kJobs / 4, "t");
    store.submit(s, ex);
  }
  std::vector<long long> claimed[2];
  auto worker = [&](int w) {
    Store store(db, false);
    const std::string owner = "w" + std::to_string(w);
    while (auto job = store.claim_next(std::nullopt, owner)) claimed[w].push_back(job->job_id);
  };
  std::thread t0(worker, 0), t1(worker, 1);
  t0.join();
  t1.join();
  std::set<long long> all(claimed[0].begin(), claimed[0].end());
  all.insert(claimed[1].begin(), claimed[1].end());
  EXPECT_EQ(claimed[0].size() + claimed[1].size(), static_cast<std::size_t>(kJobs));
  EXPECT_EQ(all.size(), static_cast<std::size_t>(kJobs));
  Store store(db, false);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'running' AND attempts = 1"), kJobs);
}

TEST(Store, RetryableFailureIsRetriedOnceThenFailed) {
  Store store(test_support::fresh_db_path("store_test", "retry"));
  auto [s, ex] = make_study("a", 1, 1, "t");
  const auto sub = store.submit(s, ex);
  ResultRow crash;
  crash.reason = "killed by signal 11";
  auto job = store.claim_next(sub.study_id, "me");
  EXPECT_TRUE(store.record_retryable_failure(job->job_id, "me", crash, 2));
  EXPECT_EQ(text(store, "SELECT status FROM jobs"), "queued");
  job = store.claim_next(sub.study_id, "me");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->attempts, 2);
  EXPECT_FALSE(store.record_retryable_failure(job->job_id, "me", crash, 2));
  EXPECT_EQ(text(store, "SELECT status FROM jobs"), "failed");
  EXPECT_EQ(text(store, "SELECT status FROM results"), "failed");
  EXPECT_NE(text(store, "SELECT reason FROM results").find("signal 11"), std::string::npos);
  EXPECT_EQ(store.refresh_study_status(sub.study_id), "running");  // series not extrapolated yet
  ASSERT_EQ(store.series_ready(sub.study_id).size(), 1u);
  store.store_extrapolation(store.series_ready(sub.study_id).front().id, {}, {});
  EXPECT_EQ(store.refresh_study_status(sub.study_id), "failed");
}

TEST(Store, OnlyTheOwnerRecordsAResult) {
  Store store(test_support::fresh_db_path("store_test", "owner"));
  auto [s, ex] = make_study("a", 1, 1, "t");
  const auto sub = store.submit(s, ex);
  auto job = store.claim_next(sub.study_id, "me");
  EXPECT_FALSE(store.record_result(job->job_id, "someone-else", converged(1, 1)));
  EXPECT_TRUE(store.record_result(job->job_id, "me", converged(1, 1)));
  EXPECT_FALSE(store.record_result(job->job_id, "me", converged(2, 1)));  // exactly one result
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);
}

TEST(Store, StaleRunningJobsOfDeadOwnersAreRequeuedOnStartup) {
  Store store(test_support::fresh_db_path("store_test", "stale"));
  auto [s, ex] = make_study("a", 1, 3, "t");
  const auto sub = store.submit(s, ex);
  const std::string dead = "nohost-that-is-this:1:1";
  const std::string live = this_process_owner();
  auto j1 = store.claim_next(sub.study_id, dead);
  auto j2 = store.claim_next(sub.study_id, live);
  ASSERT_TRUE(j1 && j2);
  EXPECT_TRUE(owner_alive(live));
  const int n = store.requeue_stale([&](const std::string& o) { return o == live; });
  EXPECT_EQ(n, 1);
  EXPECT_EQ(text(store, "SELECT status FROM jobs WHERE id = " + std::to_string(j1->job_id)), "queued");
  EXPECT_EQ(scalar(store, "SELECT attempts FROM jobs WHERE id = " + std::to_string(j1->job_id)), 0);
  EXPECT_EQ(text(store, "SELECT status FROM jobs WHERE id = " + std::to_string(j2->job_id)), "running");
}

TEST(Store, OwnerOfAFinishedProcessIsNotAlive) {
  // pid 1's start time never matches a made-up one; our own identity does.
  EXPECT_TRUE(owner_alive(this_process_owner()));
  std::string me = this_process_owner();
  const auto host = me.substr(0, me.find(':'));
  EXPECT_FALSE(owner_alive(host + ":1:999999999999"));
  EXPECT_FALSE(owner_alive(host + ":999999999:1"));
}

TEST(Store, ReleaseRequeuesWithoutSpendingAnAttempt) {
  Store store(test_support::fresh_db_path("store_test", "release"));
  auto [s, ex] = make_study("a", 1, 1, "t");
  const auto sub = store.submit(s, ex);
  auto job = store.claim_next(sub.study_id, "me");
  EXPECT_TRUE(store.release(job->job_id, "me", "interrupted"));
  EXPECT_EQ(scalar(store, "SELECT attempts FROM jobs"), 0);
  EXPECT_EQ(text(store, "SELECT status FROM jobs"), "queued");
}

TEST(Store, SeriesCompletionExtrapolationAndStudyStatus) {
  Store store(test_support::fresh_db_path("store_test", "series"));
  auto [s, ex] = make_study("a", 2, 2, "t");
  const auto sub = store.submit(s, ex);
  EXPECT_TRUE(store.series_ready(sub.study_id).empty());
  while (auto job = store.claim_next(sub.study_id, "me")) store.record_result(job->job_id, "me", converged(1159, 1));
  const auto ready = store.series_ready(sub.study_id);
  ASSERT_EQ(ready.size(), 2u);
  const auto pts = store.series_points(ready[0].id);
  ASSERT_EQ(pts.size(), 2u);
  ExtrapolationRow power{"power", 1159.0, 1.0, 1.0, std::nullopt, std::nullopt, 0.1, 0.2, 1.25, true, "ok", "{}"};
  ExtrapolationRow mixed{"mixed", 1159.1, std::nullopt, std::nullopt, 1.0, 0.0, 0.1, 0.2, 1.25, false, "ok", "{}"};
  store.store_extrapolation(ready[0].id, {power, mixed}, {{pts[0].job_id, 1.0, 1159.0, 0.5, 0.0004}});
  EXPECT_EQ(store.refresh_study_status(sub.study_id), "running");
  store.store_extrapolation(ready[1].id, {power, mixed}, {});
  EXPECT_EQ(store.refresh_study_status(sub.study_id), "done");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM extrapolations WHERE chosen = 1"), 2);
  EXPECT_EQ(store.extrapolations(ready[0].id).size(), 2u);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM v_results WHERE rde IS NOT NULL"), 1);
  EXPECT_FALSE(text(store, "SELECT finished_at FROM studies").empty());
  EXPECT_EQ(text(store, "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
}

// A grid on which numerics.stall_remedy acted carries the iteration it
// began at (the result's extra.correction_relaxed_from_iteration) to the
// report's stability map (docs/REPORTS.md); 0 for any other grid.
TEST(Store, SeriesPointsCarryTheIterationTheStallRemedyActedFrom) {
  Store store(test_support::fresh_db_path("store_test", "remedy"));
  auto [s, ex] = make_study("a", 1, 2, "t");
  const auto sub = store.submit(s, ex);
  int n = 0;
  while (auto job = store.claim_next(sub.study_id, "me")) {
    auto r = converged(1159, 1);
    if (n++ == 0) r.result_json = R"({"outcome": "converged", "extra": {"correction_relaxed_from_iteration": 239}})";
    store.record_result(job->job_id, "me", r);
  }
  const auto ready = store.series_ready(sub.study_id);
  ASSERT_EQ(ready.size(), 1u);
  const auto pts = store.series_points(ready[0].id);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].remedy_from_iteration + pts[1].remedy_from_iteration, 239);
  EXPECT_EQ(pts[0].remedy_from_iteration * pts[1].remedy_from_iteration, 0);
}

TEST(Store, CancelStopsQueuedJobsAndResubmitResumes) {
  Store store(test_support::fresh_db_path("store_test", "cancel"));
  auto [s, ex] = make_study("a", 1, 3, "t");
  const auto sub = store.submit(s, ex);
  auto running = store.claim_next(sub.study_id, "me");
  EXPECT_TRUE(store.cancel("a"));
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'cancelled'"), 2);
  EXPECT_EQ(text(store, "SELECT status FROM studies"), "cancelled");
  EXPECT_FALSE(store.claim_next(sub.study_id, "me").has_value());
  store.submit(s, ex);
  EXPECT_EQ(text(store, "SELECT status FROM studies"), "queued");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'queued'"), 2);
  EXPECT_FALSE(store.cancel("nope"));
}

}  // namespace
}  // namespace gridfree
