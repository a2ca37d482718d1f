// SPDX-License-Identifier: GPL-3.0-or-later
// The scheduler loop against a FakeExecutor (no processes): every outcome
// class (converged, not converged, invalid, crash, garbage, flaky) lands in
// the store with the right status and retry count, the study finishes, the
// series are extrapolated and the report data come out of the store.
#include <gtest/gtest.h>

#include <deque>
#include <filesystem>
#include <fstream>
#include <map>

#include "sched/outcome.h"
#include "sched/scheduler.h"
#include "sched/series_finish.h"
#include "store/owner.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) { return test_support::fresh_scratch_dir("sched_test", name); }

// Finishes jobs in start order; what each does comes from "mode" in its job.json.
class FakeExecutor : public Executor {
 public:
  void start(const JobLaunch& job) override {
    in_flight_before.push_back(queue_.size());
    started.push_back(job);
    queue_.push_back(job);
    max_in_flight = std::max(max_in_flight, queue_.size());
  }
  std::optional<JobExit> wait_any(double) override {
    if (queue_.empty()) return std::nullopt;
    const JobLaunch job = queue_.front();
    queue_.pop_front();
    std::ifstream in(job.run_dir / "job.json");
    const auto doc = nlohmann::json::parse(in);
    const std::string mode = doc["mode"];
    const double h = doc["h"];
    JobExit e;
    e.job_id = job.job_id;
    e.run_dir = job.run_dir;
    const auto write = [&](const std::string& status, const std::string& dp) {
      std::ofstream out(job.run_dir / "result.json");
      out << R"({"status": ")" << status << R"(", "reason": "fake", "srq": {"dp_star": )" << dp
          << R"(}, "grid": {"cells": [1, 1, 1], "delta_star": )" << h << "}}";
    };
    if (mode == "ok" || (mode == "flaky" && ++flaky_seen_[job.job_id] > 1)) {
      write("converged", std::to_string(1159 + h));
      e.code = 0;
    } else if (mode == "noconv") {
      write("not_converged", "null");
      e.code = 3;
    } else if (mode == "invalid") {
      e.code = 2;
    } else if (mode == "garbage") {
      std::ofstream(job.run_dir / "result.json") << "{oops";
      e.code = 0;
    } else {  // crash, and flaky's first attempt
      e.how = JobExit::How::kSignaled;
      e.signal = 11;
    }
    return e;
  }
  std::vector<long long> kill_all() override {
    std::vector<long long> ids;
    for (const auto& j : queue_) ids.push_back(j.job_id);
    queue_.clear();
    return ids;
  }
  std::size_t in_flight() const override { return queue_.size(); }
  std::string external_id(long long) const override { return ""; }

  std::vector<JobLaunch> started;
  std::vector<std::size_t> in_flight_before;  // jobs in flight when each was started
  std::size_t max_in_flight = 0;

 private:
  std::deque<JobLaunch> queue_;
  std::map<long long, int> flaky_seen_;
};

// One series per mode, each over 4 grids h = 1, 1.5, 2, 2.5.
std::pair<Study, ExpandedStudy> study_of_modes(const std::vector<std::string>& modes) {
  Study s;
  s.name = "modes";
  s.definition = {{"name", "modes"}, {"modes", modes}};
  ExpandedStudy ex;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    ex.series.push_back(SeriesKey{modes[i], "superbee", 6, "bvk", "diffusion"});
    for (int g = 0; g < 4; ++g) {
      StudyJob j;
      j.series = i;
      j.grid = static_cast<std::size_t>(g);
      j.delta_star = 1.0 + 0.5 * g;
      j.cells = {g + 1, g + 1, g + 1};
      j.doc = {{"mode", modes[i]}, {"h", j.delta_star}};
      j.hash = modes[i] + std::to_string(g);
      ex.jobs.push_back(j);
    }
  }
  return {s, ex};
}

SchedulerOptions options_for(const fs::path& dir, long long study) {
  SchedulerOptions o;
  o.study = study;
  o.workers = 2;
  o.runs_root = dir / "runs";
  o.owner = this_process_owner();
  return o;
}

std::map<std::string, std::string> job_status_by_hash(Store& store) {
  std::map<std::string, std::string> out;
  auto st = store.db().prepare("SELECT job_hash, status FROM jobs");
  while (st.step()) out[st.as_text(0)] = st.as_text(1);
  return out;
}

TEST(Scheduler, EveryOutcomeIsRecordedAndTheStudyFinishes) {
  const auto dir = temp_dir("outcomes");
  Store store(dir / "db.sqlite");
  auto [s, ex] = study_of_modes({"ok", "noconv", "invalid", "crash", "garbage", "flaky"});
  const auto sub = store.submit(s, ex);
  FakeExecutor fake;
  const auto sum = run_scheduler(store, fake, options_for(dir, sub.study_id));

  EXPECT_FALSE(sum.interrupted);
  EXPECT_LE(fake.max_in_flight, 2u);
  // ok + flaky converge (8); noconv, invalid, crash, garbage fail (16).
  EXPECT_EQ(sum.converged, 8);
  EXPECT_EQ(sum.failed, 16);
  // Retried once: each crash, garbage and flaky job (4 + 4 + 4).
  EXPECT_EQ(sum.retried, 12);
  EXPECT_EQ(fake.started.size(), 24u + 12u);
  // Every worker of the database shares one bed cache (job/bed_cache.h).
  for (const JobLaunch& l : fake.started) EXPECT_EQ(l.bed_cache, dir / "runs" / "beds");
  const auto st = job_status_by_hash(store);
  EXPECT_EQ(st.at("ok0"), "done");
  EXPECT_EQ(st.at("flaky3"), "done");
  for (const char* h : {"noconv0", "invalid1", "crash2", "garbage3"}) EXPECT_EQ(st.at(h), "failed") << h;

  auto text = [&](const std::string& sql) {
    auto q = store.db().prepare(sql);
    q.step();
    return q.as_text(0);
  };
  EXPECT_EQ(text("SELECT r.status FROM results r JOIN jobs j ON j.id = r.job_id WHERE j.job_hash = 'noconv1'"),
            "not_converged");
  EXPECT_EQ(text("SELECT r.status FROM results r JOIN jobs j ON j.id = r.job_id WHERE j.job_hash = 'invalid1'"),
            "invalid");
  EXPECT_EQ(text("SELECT attempts FROM jobs WHERE job_hash = 'crash1'"), "2");
  EXPECT_EQ(text("SELECT attempts FROM jobs WHERE job_hash = 'noconv1'"), "1");
  EXPECT_NE(text("SELECT r.reason FROM results r JOIN jobs j ON j.id = r.job_id WHERE j.job_hash = 'garbage0'")
                .find("not valid JSON"),
            std::string::npos);
  EXPECT_EQ(text("SELECT COUNT(*) FROM results"), "24");
  EXPECT_EQ(text("SELECT status FROM studies"), "failed");  // some jobs did not converge
  EXPECT_EQ(text("SELECT COUNT(*) FROM series WHERE status = 'done'"), "6");
  EXPECT_EQ(text("SELECT COUNT(*) FROM extrapolations"), "12");  // power + mixed per series
  // Verdicts (docs/EXTRAPOLATION.md): every finished series has one. 'ok' has
  // 4 exact grids f = 1159 + h: 1 degree of freedom → unreliable; 'noconv'
  // has no converged grid → insufficient_grids.
  EXPECT_EQ(text("SELECT COUNT(*) FROM series WHERE verdict IS NULL"), "0");
  EXPECT_EQ(text("SELECT verdict FROM series WHERE case_name = 'ok'"), "unreliable");
  EXPECT_NE(text("SELECT verdict_reasons FROM series WHERE case_name = 'ok'").find("1 degree(s) of freedom"),
            std::string::npos);
  EXPECT_EQ(text("SELECT verdict FROM series WHERE case_name = 'noconv'"), "insufficient_grids");
  EXPECT_EQ(text("SELECT verdict || ' ' || round(f0, 6) || ' ' || finest_delta_star FROM v_series WHERE case_name = 'ok'"),
            "unreliable 1159.0 1.0");

  const auto data = build_report_data(store, sub.study_id);
  EXPECT_EQ(data.study_name, "modes");
  ASSERT_EQ(data.series.size(), 6u);
  ASSERT_EQ(data.series[0].grids.size(), 4u);
  for (const auto& g : data.series[0].grids) {
    EXPECT_EQ(g.status, "converged");
    ASSERT_TRUE(g.dp_star);
    EXPECT_NEAR(*g.dp_star, 1159 + g.delta_star, 1e-6);  // written by the fake as 1159 + h
  }
  EXPECT_EQ(data.series[1].grids[0].status, "not_converged");
}

TEST(Scheduler, ARunOfADoneStudyStartsNothing) {
  const auto dir = temp_dir("resume");
  Store store(dir / "db.sqlite");
  auto [s, ex] = study_of_modes({"ok"});
  const auto sub = store.submit(s, ex);
  FakeExecutor first;
  run_scheduler(store, first, options_for(dir, sub.study_id));
  EXPECT_EQ(first.started.size(), 4u);
  store.submit(s, ex);
  FakeExecutor second;
  run_scheduler(store, second, options_for(dir, sub.study_id));
  EXPECT_TRUE(second.started.empty());
}

TEST(Scheduler, AStopRequestReleasesJobsInFlight) {
  const auto dir = temp_dir("stop");
  Store store(dir / "db.sqlite");
  auto [s, ex] = study_of_modes({"ok"});
  const auto sub = store.submit(s, ex);
  FakeExecutor fake;
  auto o = options_for(dir, sub.study_id);
  int polls = 0;
  o.stop_requested = [&] { return ++polls > 3; };  // stop after the first jobs started
  const auto sum = run_scheduler(store, fake, o);
  EXPECT_TRUE(sum.interrupted);
  auto q = store.db().prepare("SELECT COUNT(*) FROM jobs WHERE status = 'running'");
  q.step();
  EXPECT_EQ(q.as_int(0), 0);
  FakeExecutor again;
  run_scheduler(store, again, options_for(dir, sub.study_id));
  auto r = store.db().prepare("SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results");
  r.step();
  EXPECT_EQ(r.as_int(0), 4);
  EXPECT_EQ(r.as_int(1), 4);
}

// A study's cores rule (study/job_cores.h) through the loop: each job's
// --threads is its cores, capped by the pool's; a 2-core job on a 2-core
// pool runs alone, the 1-core jobs run two at a time.
TEST(Scheduler, CoresRuleGivesThreadsAndPacksThePool) {
  const auto dir = temp_dir("cores");
  Store store(dir / "db.sqlite");
  Study s;
  s.name = "cores";
  s.definition = {{"name", "cores"}, {"cores", "cells"}};
  ExpandedStudy ex;
  for (std::size_t i = 0; i < 2; ++i) {
    ex.series.push_back(SeriesKey{i == 0 ? "A" : "B", "superbee", 6, "bvk", "diffusion"});
    for (int g = 0; g < 4; ++g) {
      StudyJob j;
      j.series = i;
      j.grid = static_cast<std::size_t>(g);
      j.delta_star = 1.0 + 0.5 * g;
      j.cells = {g + 1, g + 1, g + 1};  // 1, 8, 27, 64 cells: 1 core, then the pool's 2
      j.doc = {{"mode", "ok"}, {"h", j.delta_star}};
      j.hash = std::string(i == 0 ? "a" : "b") + std::to_string(g);
      ex.jobs.push_back(j);
    }
  }
  const auto sub = store.submit(s, ex);
  FakeExecutor fake;
  SchedulerOptions o = options_for(dir, sub.study_id);
  o.workers = 2;
  o.threads_per_job = 1;
  o.cores = 2;
  const auto sum = run_scheduler(store, fake, o);
  EXPECT_EQ(sum.converged, 8);
  ASSERT_EQ(fake.started.size(), 8u);
  int one_core_beside_another = 0;
  for (std::size_t k = 0; k < fake.started.size(); ++k) {
    const JobLaunch& l = fake.started[k];
    const int expected = l.cells[0] == 1 ? 1 : 2;
    EXPECT_EQ(l.threads, expected) << l.cells[0];
    EXPECT_EQ(l.cores, expected);
    if (expected == 2) {
      EXPECT_EQ(fake.in_flight_before[k], 0u) << "a 2-core job started beside another";
    }
    if (expected == 1 && fake.in_flight_before[k] == 1) ++one_core_beside_another;
  }
  EXPECT_EQ(one_core_beside_another, 1);  // the two 1-core jobs ran together
}

TEST(Outcome, ExitCodesMapToTheFailureClasses) {
  const auto dir = temp_dir("classify");
  JobExit e;
  e.run_dir = dir;
  e.how = JobExit::How::kExited;
  e.code = 0;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);  // exit 0, no result file
  std::ofstream(dir / "result.json") << R"({"status": "converged", "srq": {"dp_star": 1158.8}})";
  auto ok = classify_exit(e);
  EXPECT_EQ(ok.kind, OutcomeKind::kFinal);
  EXPECT_EQ(ok.row.status, "converged");
  EXPECT_DOUBLE_EQ(*ok.row.dp_star, 1158.8);
  std::ofstream(dir / "result.json") << R"({"status": "diverged", "reason": "NaN in p"})";
  e.code = 3;
  auto div = classify_exit(e);
  EXPECT_EQ(div.kind, OutcomeKind::kFinal);
  EXPECT_EQ(div.row.status, "diverged");
  EXPECT_EQ(div.row.reason, "NaN in p");
  e.code = 2;
  EXPECT_EQ(classify_exit(e).row.status, "invalid");
  e.code = 1;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);
  e.how = JobExit::How::kTimedOut;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);
  e.how = JobExit::How::kKilled;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kReleased);
  std::ofstream(dir / "result.json") << R"({"status": "converged"})";  // no dp_star
  e.how = JobExit::How::kExited;
  e.code = 0;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);
}

}  // namespace
}  // namespace gridfree
