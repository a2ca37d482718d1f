// SPDX-License-Identifier: GPL-3.0-or-later
// Store: re-collection of external jobs (docs/EXTERNAL.md "The study"). A
// finished external job's result records the collect section it was read
// with ("collected_with", sched/external_result.h); when the study's
// collect section changes, the job (same hash) is read again, not rerun.
#include "store/store.h"

namespace gridfree {
namespace {

const nlohmann::json* collect_of_spec(const nlohmann::json& spec) {
  if (!spec.is_object() || !spec.contains("case") || !spec["case"].is_object()) return nullptr;
  const auto& c = spec["case"];
  if (!c.contains("external") || !c["external"].is_object() || !c["external"].contains("collect")) return nullptr;
  return &c["external"]["collect"];
}

}  // namespace

std::vector<ClaimedJob> Store::jobs_to_recollect(long long study_id) {
  std::vector<ClaimedJob> out;
  auto st = db_.prepare(
      "SELECT DISTINCT j.id, j.job_hash, j.spec_json, r.result_json FROM study_jobs sj "
      "JOIN jobs j ON j.id = sj.job_id JOIN results r ON r.job_id = j.id "
      "WHERE sj.study_id = ? AND j.status IN ('done','failed') AND r.result_json IS NOT NULL "
      "AND json_valid(j.spec_json) AND json_extract(j.spec_json, '$.case.external') IS NOT NULL ORDER BY j.id");
  st.bind_all(study_id);
  while (st.step()) {
    const auto spec = nlohmann::json::parse(st.as_text(2), nullptr, false);
    const auto result = nlohmann::json::parse(st.as_text(3), nullptr, false);
    const nlohmann::json* collect = collect_of_spec(spec);
    if (collect == nullptr || !result.is_object()) continue;
    if (result.contains("collected_with") && result["collected_with"] == *collect) continue;
    ClaimedJob job;
    job.job_id = st.as_int(0);
    job.study_id = study_id;
    job.job_hash = st.as_text(1);
    job.spec = spec;
    out.push_back(std::move(job));
  }
  return out;
}

void Store::record_recollected(long long job_id, const ResultRow& r) {
  Transaction tx(db_);
  // The run's own time and memory stay (cost history); what was read is new.
  auto old = db_.prepare("SELECT result_json FROM results WHERE job_id = ?");
  old.bind_all(job_id);
  auto doc = nlohmann::json::parse(r.result_json.empty() ? std::string("{}") : r.result_json, nullptr, false);
  if (old.step() && doc.is_object()) {
    const auto before = nlohmann::json::parse(old.as_text(0), nullptr, false);
    if (before.is_object())
      for (const char* key : {"timing", "memory"})
        if (before.contains(key)) doc[key] = before[key];
  }
  old.reset();
  db_.prepare(
         "UPDATE results SET status = ?, dp_star = ?, reason = ?, result_json = ?, "
         "recorded_at = strftime('%Y-%m-%dT%H:%M:%fZ','now') WHERE job_id = ?")
      .bind_all(r.status, r.dp_star, r.reason, doc.is_object() ? doc.dump() : r.result_json, job_id)
      .run();
  db_.prepare("UPDATE jobs SET status = ?, error = ? WHERE id = ?")
      .bind_all(r.status == "converged" ? "done" : "failed",
                r.status == "converged" ? std::optional<std::string>() : std::optional<std::string>(r.status + ": " + r.reason),
                job_id)
      .run();
  // Its series extrapolate again with the new values (a daemon may have
  // finished them with the old ones after the study was replaced).
  db_.prepare("UPDATE series SET status = 'queued' WHERE status = 'done' AND id IN "
              "(SELECT series_id FROM study_jobs WHERE job_id = ?)")
      .bind_all(job_id)
      .run();
  db_.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'recollect', ?)")
      .bind_all(job_id, r.status + (r.reason.empty() ? "" : ": " + r.reason)).run();
  tx.commit();
}

}  // namespace gridfree
