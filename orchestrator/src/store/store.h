// SPDX-License-Identifier: GPL-3.0-or-later
// The study/job store: SQLite in WAL mode (schema.h), shared by any number
// of `gridfree run`/`daemon` processes. Every state change is one
// transaction; a job is claimed inside BEGIN IMMEDIATE, so two processes
// never run the same job. Job state machine:
//
//   queued --claim--> running --result--> done (converged) | failed (other)
//      ^                 |  \--crash/timeout/garbage, attempts < max--> queued
//      |                 \--owner process gone (requeue_stale) / released--> queued
//   cancelled <--cancel-- queued
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/sqlite.h"
#include "study/study.h"

namespace gridfree {

struct SubmitResult {
  long long study_id = 0;
  bool created = false;          // false: same study already there (resume)
  std::size_t jobs_total = 0;
  std::size_t jobs_new = 0;      // inserted by this submit
  std::size_t jobs_reused = 0;   // already done in the store (any study)
  bool replaced = false;         // a different stored definition was replaced (--replace)
  bool jobs_changed = false;     // replaced because an external study's jobs changed (template, version)
  bool uncancelled = false;      // the stored study was cancelled and is queued again
  std::size_t jobs_requeued = 0; // its cancelled jobs queued again
  // Hashes of the jobs the replaced study linked that no study links now:
  // kept with their results and run folders, reusable (a queued one is
  // cancelled: nothing needs it run); `gridfree gc` removes them
  // (store/unneeded_jobs.h).
  std::vector<std::string> jobs_unneeded;
};

struct ClaimedJob {
  long long job_id = 0;
  long long study_id = 0;
  std::string job_hash;
  nlohmann::json spec;           // the job document
  int attempts = 0;              // including this one
  std::array<int, 3> cells{};
};

// What the worker produced, ready to store (status: converged |
// not_converged | diverged | invalid | failed).
struct ResultRow {
  std::string status = "failed";
  std::optional<double> dp_star;
  double delta_star = 0;
  std::array<int, 3> cells{};
  int iterations = 0;
  double wall_s = 0, cpu_s = 0, peak_rss_mb = 0;
  std::string reason;
  std::string result_json;       // the result document, or "" when there is none
};

struct SeriesInfo {
  long long id = 0, study_id = 0;
  SeriesKey key;
  std::string status;
  std::string verdict;           // converged | pre-asymptotic | unreliable | insufficient_grids | "" (none yet)
  std::string verdict_reasons;   // JSON array of sentences, or ""
  std::string coverage_json;     // the coverage self-check (extrap/self_check.h) as JSON, or ""
};

struct VerdictRow {              // docs/EXTRAPOLATION.md "Verdicts"
  std::string value;
  std::string reasons_json;      // JSON array of sentences
};

struct SeriesPoint {             // one job of a series, with its result if any
  long long job_id = 0;
  std::string job_hash, job_status, result_status, reason;
  double delta_star = 0;
  std::array<int, 3> cells{};
  std::optional<double> dp_star;
  int iterations = 0;
  double wall_s = 0, cpu_s = 0, peak_rss_mb = 0;
  std::string worker_outcome;    // the result's `outcome` (stalled | iteration_cap ...), '' before it existed
  int remedy_from_iteration = 0; // extra.correction_relaxed_from_iteration (numerics.stall_remedy), 0 if none
};

struct ExtrapolationRow {
  std::string method;            // power | mixed | capped | first | second | constant
  std::optional<double> f0, p, c, c1, c2, sigma_re, data_range, fs;
  bool chosen = false;
  std::string status;            // ok | insufficient_grids | p_not_found ...
  std::string detail_json;
};

struct UncertaintyRow {
  long long job_id = 0;
  double delta_star = 0;
  std::optional<double> f, u, rde;
};

struct StudyStatus {
  long long id = 0;
  std::string name, status, submitted_at, finished_at, design;
  int jobs = 0, queued = 0, running = 0, done = 0, failed = 0, cancelled = 0;
  int converged = 0;             // results with status converged
  int series = 0, series_done = 0;
  double mean_wall_s = 0;        // over this study's finished jobs
};

class Store {
 public:
  // Opens the database; `create` also creates the file. Migrates the schema.
  explicit Store(const std::filesystem::path& file, bool create = true);

  Database& db() { return db_; }
  const std::filesystem::path& file() const { return file_; }

  // Adds a study, its series and jobs in one transaction. The same name with
  // the same definition is a resume (no-op; a cancelled study is queued
  // again); the same name with another definition throws InputError unless
  // `replace`: then the stored study is removed as by delete_study (in the
  // same transaction) and the new one inserted; jobs both need, finished
  // or not, are kept and linked again (job_hash).
  // An external study whose file is unchanged but whose jobs are not (its
  // template or code version changed) is replaced without `replace`.
  SubmitResult submit(const Study& study, const ExpandedStudy& expanded, bool replace = false);
  // The hashes of the jobs a stored study links.
  std::set<std::string> stored_job_hashes(long long study_id);

  // Re-collection (store_recollect.cpp): a study's finished external jobs
  // whose result was collected with another collect section than their job
  // document's (the study's collect changed), with their job documents.
  std::vector<ClaimedJob> jobs_to_recollect(long long study_id);
  // Replaces what was read of a finished job (status, quantities, reason);
  // its run time and memory stay. The job becomes done or failed by it.
  void record_recollected(long long job_id, const ResultRow& r);

  // Removes a study: its series, extrapolations, uncertainties, job links
  // and events; then those of its jobs that no study links any more, with
  // their results (jobs shared with other studies stay, and so do jobs
  // other studies left unneeded: `gridfree gc` removes those). Throws
  // InputError while one of its jobs is running. Returns the removed jobs'
  // hashes (their run folders can go too), or nullopt when there is no
  // such study.
  std::optional<std::vector<std::string>> delete_study(const std::string& name);

  std::optional<long long> study_id(const std::string& name);
  std::vector<long long> active_studies();      // queued | running, oldest first

  // Claims the next queued job (of `study`, or of any active study in
  // submission order): running, attempts + 1, owner recorded. Atomic.
  // `job`: claim exactly this queued job (the scheduler's budget chose it).
  std::optional<ClaimedJob> claim_next(std::optional<long long> study, const std::string& owner,
                                       std::optional<long long> job = std::nullopt);

  // Records the final result of a running job owned by `owner` (job → done
  // when converged, failed otherwise). False if the job is no longer ours.
  bool record_result(long long job_id, const std::string& owner, const ResultRow& r);

  // A failure worth one more try (crash, timeout, garbage): queued again
  // while attempts < max_attempts, else recorded as a failed result.
  // Returns true when the job was requeued.
  bool record_retryable_failure(long long job_id, const std::string& owner, const ResultRow& r,
                                int max_attempts);

  // Puts a running job back to queued without spending an attempt
  // (interrupted by a shutdown). False if the job is not ours.
  bool release(long long job_id, const std::string& owner, const std::string& why);

  // Requeues running jobs whose owner process is gone; returns their count.
  int requeue_stale(const std::function<bool(const std::string& owner)>& alive);

  // Adoption after a crash (store_adopt.cpp): running jobs whose owner is
  // gone and whose external id starts with `prefix` ("slurm:"), or is not
  // recorded yet (killed between submission and recording), become
  // `owner`'s, attempts unchanged, in one transaction. Returned with their
  // external id and run folder so the executor can watch them again.
  struct Adopted {
    ClaimedJob job;
    std::string external_id;
    std::filesystem::path run_dir;
  };
  std::vector<Adopted> take_over_stale(const std::function<bool(const std::string& owner)>& alive,
                                       const std::string& owner, const std::string& prefix);
  // The queue's state and pending reason of a job (NULL for local jobs).
  void set_queue_state(long long job_id, const std::string& external_id, const std::string& state,
                       const std::string& reason);
  // A study's running jobs that sit in an external queue, for `status`.
  struct QueuedJob {
    long long job_id = 0;
    std::string label, external_id, state, reason;
  };
  std::vector<QueuedJob> queue_jobs(long long study_id);
  // Puts a study's failed jobs back in the queue with their attempts reset,
  // their series and the study open again; returns how many.
  int retry_failed(long long study_id);

  void set_job_external_id(long long job_id, const std::string& external_id);
  void set_job_paths(long long job_id, const std::string& result_path);

  // Series whose jobs have all reached done/failed/cancelled but which are
  // not marked done yet (ready for extrapolation).
  std::vector<SeriesInfo> series_ready(long long study_id);
  // The same, among the series the job belongs to (in the study): what one
  // finished job can make ready, at a cost independent of the study's size.
  std::vector<SeriesInfo> series_ready_of_job(long long study_id, long long job_id);
  std::vector<SeriesInfo> series_of_study(long long study_id);
  std::vector<SeriesPoint> series_points(long long series_id);

  // Stores both fits, the per-job uncertainties and the verdict (when
  // given), marks the series done.
  void store_extrapolation(long long series_id, const std::vector<ExtrapolationRow>& fits,
                           const std::vector<UncertaintyRow>& uncertainties,
                           const std::optional<VerdictRow>& verdict = std::nullopt);
  // The series' coverage self-check as JSON (extrap/self_check.h to_ordered_json).
  void store_coverage(long long series_id, const std::string& json);
  std::vector<ExtrapolationRow> extrapolations(long long series_id);
  std::vector<UncertaintyRow> uncertainties(long long series_id);

  // Study status from its jobs and series: running while work is left,
  // done when every job converged, failed when some did not; cancelled stays.
  std::string refresh_study_status(long long study_id);

  // Cancels a study: it and its queued jobs (unless another active study
  // needs them) become cancelled. Running jobs finish. False if unknown.
  bool cancel(const std::string& name);

  std::vector<StudyStatus> statuses(std::optional<long long> study = std::nullopt);
  nlohmann::json study_definition(long long study_id);
  void log_event(std::optional<long long> study_id, std::optional<long long> job_id,
                 const std::string& kind, const std::string& message);

 private:
  void remove_study_rows(long long study_id, const std::string& name);  // inside a transaction
  std::vector<long long> study_job_ids(long long study_id);

  std::filesystem::path file_;
  Database db_;
};

}  // namespace gridfree
