// SPDX-License-Identifier: GPL-3.0-or-later
// Store: opening, submitting a study (one transaction), cancelling.
#include <set>

#include "core/input_error.h"
#include "store/database_file.h"
#include "store/schema.h"
#include "store/store_ensembles.h"
#include "study/case_kind.h"
#include "store/store.h"
#include "store/store_alignment.h"
#include "store/unneeded_jobs.h"

namespace gridfree {
namespace {

std::set<std::string> expanded_job_hashes(const ExpandedStudy& expanded) {
  std::set<std::string> out;
  for (const auto& j : expanded.jobs) out.insert(j.hash);
  for (const auto& a : expanded.alignment) out.insert(a.hash);
  return out;
}

}  // namespace

// The file is checked before SQLite opens it (a directory, a missing folder,
// not a SQLite file); what SQLite says about it while opening is put in the
// user's words (store/database_file.h).
Store::Store(const std::filesystem::path& file, bool create) try
    : file_((check_database_file(file, create), file)), db_(file, create) {
  migrate(db_);
} catch (const SqliteError& e) {
  if (auto problem = database_file_error(file, e)) throw *problem;
  throw;
}

std::optional<long long> Store::study_id(const std::string& name) {
  auto st = db_.prepare("SELECT id FROM studies WHERE name = ?");
  st.bind_all(name);
  if (!st.step()) return std::nullopt;
  return st.as_int(0);
}

nlohmann::json Store::study_definition(long long id) {
  auto st = db_.prepare("SELECT definition_json FROM studies WHERE id = ?");
  st.bind_all(id);
  if (!st.step()) return nullptr;
  return nlohmann::json::parse(st.as_text(0));
}

std::set<std::string> Store::stored_job_hashes(long long study_id) {
  std::set<std::string> out;
  auto st = db_.prepare("SELECT j.job_hash FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id WHERE sj.study_id = ?");
  st.bind_all(study_id);
  while (st.step()) out.insert(st.as_text(0));
  return out;
}

SubmitResult Store::submit(const Study& study, const ExpandedStudy& expanded, bool replace) {
  // Stored as JSON text; compared as JSON values (key order, 20 vs 20.0 do not matter).
  const std::string definition = study.definition.dump();
  SubmitResult out;
  std::vector<long long> old_jobs;  // the replaced study's
  const CaseKind& kind = case_kind(study);
  // A job that serves several series (an external case's quantities) is counted once.
  out.jobs_total = kind.job_serves_several_series() ? expanded_job_hashes(expanded).size() : expanded.jobs.size();
  Transaction tx(db_);
  {
    auto st = db_.prepare("SELECT id, definition_json, status FROM studies WHERE name = ?");
    st.bind_all(study.name);
    // Where it runs (the "slurm" settings) is not what the study is.
    auto same = [](nlohmann::json d) {
      if (d.is_object()) d.erase("slurm");
      return d;
    };
    const bool exists = st.step();
    const bool changed = exists && same(nlohmann::json::parse(st.as_text(1))) != same(study.definition);
    // A study's file can stay as it was while its jobs change (an external
    // template file edited, another version of the code): its jobs are
    // then replaced as by --replace, without asking.
    const bool jobs_changed = exists && !changed && kind.jobs_follow_outside_files() &&
                              stored_job_hashes(st.as_int(0)) != expanded_job_hashes(expanded);
    if (jobs_changed) replace = true;
    if ((changed || jobs_changed) && !replace)
      throw InputError("/name", "a different study named '" + study.name + "' is already in " +
                                    file_.filename().string() +
                                    "; run it with --replace to replace the stored one (finished jobs it "
                                    "shares are reused), rename the study, or use another --db");
    if (changed || jobs_changed) {
      const long long old_id = st.as_int(0);
      st.reset();
      old_jobs = study_job_ids(old_id);
      remove_study_rows(old_id, study.name);
      out.replaced = true;
      out.jobs_changed = jobs_changed;
    } else if (exists) {
      out.study_id = st.as_int(0);
      const bool cancelled = st.as_text(2) == "cancelled";
      if (cancelled) {
        auto up = db_.prepare(
            "UPDATE jobs SET status = 'queued', error = NULL WHERE status = 'cancelled' AND id IN "
            "(SELECT job_id FROM study_jobs WHERE study_id = ?)");
        up.bind_all(out.study_id).run();
        out.uncancelled = true;
        out.jobs_requeued = static_cast<std::size_t>(db_.changes());
        db_.prepare("UPDATE series SET status = 'queued' WHERE study_id = ? AND status = 'cancelled'")
            .bind_all(out.study_id).run();
        db_.prepare("UPDATE studies SET status = 'queued', finished_at = NULL WHERE id = ?")
            .bind_all(out.study_id).run();
      }
      tx.commit();
      return out;
    }
  }
  nlohmann::json extrap = {{"weights", study.extrapolation.weights},
                           {"p_range", {study.extrapolation.p_low, study.extrapolation.p_high}},
                           {"method", study.extrapolation.method}};
  db_.prepare("INSERT INTO studies(name, definition_json, design, extrapolation_json) VALUES (?, ?, ?, ?)")
      .bind_all(study.name, definition, study.design_description(), extrap.dump())
      .run();
  out.study_id = db_.last_insert_rowid();
  out.created = true;
  insert_ensembles(db_, out.study_id, study.ensembles);

  std::vector<long long> series_ids;
  auto ins_series = db_.prepare(
      "INSERT INTO series(study_id, position, case_name, convection, fwhm_dp, drag, deposition, quantity, levels) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < expanded.series.size(); ++i) {
    const auto& k = expanded.series[i];
    ins_series.reset();
    // A series without particle-bed factors: NULL, not "" or 0 (docs/DATABASE.md).
    const bool bed = case_kind(k).has_bed_columns();
    const auto bed_only = [&](const auto& v) { return bed ? std::optional(v) : std::nullopt; };
    ins_series.bind_all(out.study_id, static_cast<long long>(i), k.case_name, bed_only(k.convection),
                        bed_only(k.fwhm_dp), bed_only(k.drag), bed_only(k.deposition), k.quantity,
                        levels_json(k.levels)).run();
    series_ids.push_back(db_.last_insert_rowid());
  }
  auto ins_job = db_.prepare(
      "INSERT OR IGNORE INTO jobs(job_hash, spec_json, nx, ny, nz, cells, delta_star) "
      "VALUES (?, ?, ?, ?, ?, ?, ?)");
  auto find_job = db_.prepare("SELECT id, status FROM jobs WHERE job_hash = ?");
  auto requeue = db_.prepare("UPDATE jobs SET status = 'queued', error = NULL WHERE id = ? AND status = 'cancelled'");
  auto link = db_.prepare(
      "INSERT OR IGNORE INTO study_jobs(study_id, job_id, series_id, grid_index, delta_star_nominal) "
      "VALUES (?, ?, ?, ?, ?)");
  std::set<std::string> counted;  // reused jobs, each once
  for (const auto& job : expanded.jobs) {
    const long long cells = static_cast<long long>(job.cells[0]) * job.cells[1] * job.cells[2];
    ins_job.reset();
    ins_job.bind_all(job.hash, job.doc.dump(), job.cells[0], job.cells[1], job.cells[2], cells, job.delta_star)
        .run();
    const bool inserted = db_.changes() > 0;
    // A job's document may differ from the stored one in what is not its
    // identity (where an external template is, how quantities are read):
    // the study's now is the one to run and collect with (re-collection).
    if (!inserted && kind.jobs_follow_outside_files())
      db_.prepare("UPDATE jobs SET spec_json = ? WHERE job_hash = ?").bind_all(job.doc.dump(), job.hash).run();
    find_job.reset();
    find_job.bind_all(job.hash);
    find_job.step();
    const long long job_id = find_job.as_int(0);
    const std::string status = find_job.as_text(1);
    if (inserted)
      ++out.jobs_new;
    else if (status == "done" && (!kind.job_serves_several_series() || counted.insert(job.hash).second))
      ++out.jobs_reused;
    requeue.reset();
    requeue.bind_all(job_id).run();
    link.reset();
    link.bind_all(out.study_id, job_id, series_ids.at(job.series), static_cast<long long>(job.grid),
                  job.delta_star_nominal).run();
  }
  store_series_transfer(db_, series_ids, expanded);                                 // step 5 columns
  out.jobs_new += store_alignment_jobs(db_, out.study_id, series_ids, expanded);  // alignment variants
  out.jobs_total += expanded.alignment.size();
  // Jobs only the replaced study used stay, reusable (store/unneeded_jobs.h).
  if (out.replaced) out.jobs_unneeded = keep_unlinked_jobs(db_, old_jobs);
  db_.prepare("INSERT INTO events(study_id, kind, message) VALUES (?, 'submit', ?)")
      .bind_all(out.study_id, std::to_string(out.jobs_total) + " jobs, " + std::to_string(out.jobs_new) +
                                  " new, " + std::to_string(out.jobs_reused) + " already done")
      .run();
  tx.commit();
  return out;
}

bool Store::cancel(const std::string& name) {
  Transaction tx(db_);
  auto id = study_id(name);
  if (!id) return false;
  // Queued jobs of this study that no other active study shares.
  db_.prepare(
         "UPDATE jobs SET status = 'cancelled', error = 'study cancelled' WHERE status = 'queued' AND id IN "
         "(SELECT job_id FROM study_jobs WHERE study_id = ?1) AND id NOT IN "
         "(SELECT sj.job_id FROM study_jobs sj JOIN studies s ON s.id = sj.study_id "
         " WHERE sj.study_id <> ?1 AND s.status IN ('queued','running'))")
      .bind_all(*id).run();
  db_.prepare("UPDATE series SET status = 'cancelled' WHERE study_id = ? AND status IN ('queued','running')")
      .bind_all(*id).run();
  db_.prepare(
         "UPDATE studies SET status = 'cancelled', finished_at = strftime('%Y-%m-%dT%H:%M:%fZ','now') "
         "WHERE id = ? AND status IN ('queued','running')")
      .bind_all(*id).run();
  db_.prepare("INSERT INTO events(study_id, kind, message) VALUES (?, 'cancel', 'study cancelled')")
      .bind_all(*id).run();
  tx.commit();
  return true;
}

void Store::log_event(std::optional<long long> study, std::optional<long long> job, const std::string& kind,
                      const std::string& message) {
  db_.prepare("INSERT INTO events(study_id, job_id, kind, message) VALUES (?, ?, ?, ?)")
      .bind_all(study, job, kind, message).run();
}

}  // namespace gridfree
