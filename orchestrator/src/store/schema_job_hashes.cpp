// SPDX-License-Identifier: GPL-3.0-or-later
// Step 11 — job identity from the normalised document (job/job_normalise.h):
// every job whose stored hash is the one this solver version gave before
// defaults were filled in (job_hash_before_defaults of its spec_json) gets
// job_hash(spec_json). Jobs hashed by another solver version keep theirs
// (their results are not this solver's). Jobs that now share a hash — a
// default left out in one study and written in another — become one: the
// job kept is the furthest along (done, running, failed, queued, cancelled;
// then the oldest), the others' study links, alignment rows, uncertainties
// and events move to it and they are removed with their results. Each
// changed hash is logged as a 'rehash' event with the old hash; a run
// folder stays under the old hash (a finished job's result_path still
// names it; a checkpoint there is not resumed, the job starts over).
// An sscp_like bed without "emulsion" was a lattice when the job was made
// (the random emulsion became the default with this step): its spec_json
// and hash say "emulsion": "lattice", so its result is never served for a
// random bed, and a rerun of it builds the bed it was defined with.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/job_hash.h"
#include "store/schema_steps.h"

namespace gridfree {
namespace {

struct StoredJob {
  long long id = 0;
  std::string hash, status;
  std::string lattice_spec;  // the spec with "emulsion": "lattice" written, when it was a lattice-era sscp_like job
};

// Writes "emulsion": "lattice" into an sscp_like generator that has none.
bool mark_lattice_emulsion(nlohmann::json& spec) {
  if (!spec.is_object() || !spec.contains("case") || !spec["case"].is_object()) return false;
  auto& c = spec["case"];
  if (!c.contains("particles") || !c["particles"].is_object() || !c["particles"].contains("generator")) return false;
  auto& g = c["particles"]["generator"];
  if (!g.is_object() || g.value("kind", "") != "sscp_like" || g.contains("emulsion")) return false;
  g["emulsion"] = "lattice";
  return true;
}

int progress_rank(const std::string& status) {
  if (status == "done") return 0;
  if (status == "running") return 1;
  if (status == "failed") return 2;
  if (status == "queued") return 3;
  return 4;  // cancelled
}

// Moves every reference to job `from` onto job `to`, then removes `from`.
void merge_job(Database& db, long long from, long long to) {
  for (const char* sql : {
           "UPDATE OR IGNORE study_jobs SET job_id = ?2 WHERE job_id = ?1",
           "UPDATE OR IGNORE alignment_jobs SET job_id = ?2 WHERE job_id = ?1",
           "UPDATE alignment_jobs SET base_job_id = ?2 WHERE base_job_id = ?1",
           "UPDATE OR IGNORE uncertainties SET job_id = ?2 WHERE job_id = ?1",
           "UPDATE events SET job_id = ?2 WHERE job_id = ?1",
       })
    db.prepare(sql).bind_all(from, to).run();
  // What could not move (the kept job is already there) goes with the job.
  for (const char* sql : {
           "DELETE FROM study_jobs WHERE job_id = ?1",
           "DELETE FROM alignment_jobs WHERE job_id = ?1",
           "DELETE FROM uncertainties WHERE job_id = ?1",
           "DELETE FROM results WHERE job_id = ?1",
           "DELETE FROM jobs WHERE id = ?1",
       })
    db.prepare(sql).bind_all(from).run();
}

}  // namespace

void migrate_job_hashes(Database& db) {
  // The new hash of every job, grouped: hash -> jobs that have it.
  std::map<std::string, std::vector<StoredJob>> by_hash;
  {
    auto st = db.prepare("SELECT id, job_hash, spec_json, status FROM jobs ORDER BY id");
    while (st.step()) {
      StoredJob j{st.as_int(0), st.as_text(1), st.as_text(3), {}};
      std::string now = j.hash;
      auto spec = nlohmann::json::parse(st.as_text(2), nullptr, false);
      if (!spec.is_discarded() && job_hash_before_defaults(spec) == j.hash) {
        if (mark_lattice_emulsion(spec)) j.lattice_spec = spec.dump();
        now = job_hash(spec);
      }
      by_hash[now].push_back(std::move(j));
    }
  }
  auto rehash = db.prepare("UPDATE jobs SET job_hash = ? WHERE id = ?");
  auto respec = db.prepare("UPDATE jobs SET spec_json = ? WHERE id = ?");
  auto event = db.prepare("INSERT INTO events(job_id, kind, message) VALUES (?, 'rehash', ?)");
  // Merges first: a kept job's new hash may be another's old one.
  std::vector<std::pair<long long, std::string>> renames;
  for (auto& [hash, jobs] : by_hash) {
    std::size_t keep = 0;
    for (std::size_t i = 1; i < jobs.size(); ++i)
      if (progress_rank(jobs[i].status) < progress_rank(jobs[keep].status)) keep = i;
    for (std::size_t i = 0; i < jobs.size(); ++i)
      if (i != keep) merge_job(db, jobs[i].id, jobs[keep].id);
    if (jobs[keep].hash != hash) renames.emplace_back(jobs[keep].id, hash);
    if (!jobs[keep].lattice_spec.empty()) {
      respec.reset();
      respec.bind_all(jobs[keep].lattice_spec, jobs[keep].id).run();
    }
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (jobs[i].hash == hash) continue;
      event.reset();
      event
          .bind_all(jobs[keep].id, "job hash " + jobs[i].hash + " -> " + hash +
                                       (i == keep ? " (defaults filled in)" : " (one job with job " +
                                                                                 std::to_string(jobs[keep].id) + ")"))
          .run();
    }
  }
  for (const auto& [id, hash] : renames) {
    rehash.reset();
    rehash.bind_all(hash, id).run();
  }
}

}  // namespace gridfree
