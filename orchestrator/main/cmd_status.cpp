// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree status [STUDY] [--json] (with STUDY: series, running jobs, ETA) | report STUDY [--out DIR] | cancel STUDY
#include <algorithm>
#include <iostream>
#include <optional>

#include "cmd_study.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "exec/executor.h"
#include "report/extrapolator.h"
#include "sched/series_finish.h"
#include "sched/stability_status.h"
#include "sched/stop_signal.h"
#include "sched/study_status.h"
#include "store/orphans.h"

namespace gridfree::cli {
namespace {

// What a study is doing now, as opposed to its stored status: a "running"
// study none of whose jobs a live process works on (its run or daemon was
// stopped or killed) is "queued" while it has queued (or orphaned) jobs,
// else "idle".
std::string shown_status(const StudyStatus& s, const RunningJobs& r) {
  if (s.status != "running" || !r.live.empty()) return s.status;
  return s.queued > 0 || !r.orphaned.empty() ? "queued" : "idle";
}

nlohmann::json status_json(const StudyStatus& s, const RunningJobs& r) {
  const int live = static_cast<int>(r.live.size()), orphaned = static_cast<int>(r.orphaned.size());
  return {{"name", s.name},          {"status", shown_status(s, r)}, {"stored_status", s.status},
          {"submitted_at", s.submitted_at}, {"finished_at", s.finished_at}, {"design", s.design},
          {"jobs", s.jobs},          {"queued", s.queued},       {"running", live},
          {"orphaned", orphaned},    {"done", s.done},           {"failed", s.failed},
          {"cancelled", s.cancelled}, {"converged", s.converged}, {"series", s.series},
          {"series_done", s.series_done}};
}

// The detail of a study as it is now: orphaned jobs out of the running list,
// and no ETA while no live process works on the study (it would only say
// how long the work takes once someone runs it).
void mark_orphans(nlohmann::json& d, const RunningJobs& r) {
  nlohmann::json running = nlohmann::json::array();
  for (const auto& row : d["running"])
    if (!row.contains("job") || !r.orphaned.count(row["job"].get<long long>())) running.push_back(row);
  d["running"] = running;
  d["orphaned"] = r.orphaned.size();
  const bool work_left = d["eta"]["seconds"].is_number() && d["eta"]["seconds"].get<double>() > 0;
  if (r.live.empty() && work_left) {
    d["eta"]["seconds"] = nullptr;
    d["eta"]["text"] = nullptr;
  }
}

// The study's extrapolation method, declared order and the method's measured
// coverage (docs/EXTRAPOLATION.md "Coverage on other codes' series").
nlohmann::json extrapolation_json(Store& store, long long study_id) {
  const ExtrapolatorSettings e = study_extrapolation_settings(store, study_id);
  return {{"method", e.method},
          {"expected_order", e.expected_order ? nlohmann::json(*e.expected_order) : nlohmann::json(nullptr)},
          {"measured_coverage", measured_coverage_line(e.method, e.expected_order.has_value())}};
}

}  // namespace

void add_status_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("status", "studies and their jobs");
  auto name = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  auto json = std::make_shared<bool>(false);
  sub->add_option("STUDY", *name, "one study (default: all)");
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->add_flag("--json", *json, "print JSON");
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    std::optional<long long> id;
    if (!name->empty()) id = require_study(*store, *name);
    const auto rows = store->statuses(id);
    const auto queue = id ? store->queue_jobs(*id) : std::vector<Store::QueuedJob>{};
    const auto running = running_jobs_by_study(*store, id);
    auto running_of = [&running](long long study_id) {
      const auto it = running.find(study_id);
      return it == running.end() ? RunningJobs{} : it->second;
    };
    std::optional<nlohmann::json> detail;
    if (id && !rows.empty()) {
      detail = study_detail(*store, *id, runs_root_for(*db));
      mark_orphans(*detail, running_of(*id));
    }
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& s : rows) out.push_back(status_json(s, running_of(s.id)));
      if (id && !out.empty()) {  // Slurm jobs of the named study: id, state, pending reason
        nlohmann::json q = nlohmann::json::array();
        for (const auto& j : queue)
          q.push_back({{"job", j.job_id}, {"grid", j.label}, {"slurm_id", j.external_id.substr(6)},
                       {"state", j.state}, {"reason", j.reason}});
        out[0]["slurm"] = q;
      }
      if (detail) out[0]["detail"] = *detail;
      if (id && !out.empty()) out[0]["stability"] = stability_status(*store, *id);  // outcome per grid
      if (id && !out.empty()) out[0]["extrapolation"] = extrapolation_json(*store, *id);
      std::cout << out.dump(2) << '\n';
    } else {
      std::printf("%-28s %-10s %6s %6s %7s %8s %6s %6s %9s %9s %11s\n", "study", "status", "jobs", "queued",
                  "running", "orphaned", "done", "failed", "cancelled", "converged", "series done");
      for (const auto& s : rows) {
        const RunningJobs r = running_of(s.id);
        std::printf("%-28s %-10s %6d %6d %7zu %8zu %6d %6d %9d %9d %7d/%-3d\n", s.name.c_str(),
                    shown_status(s, r).c_str(), s.jobs, s.queued, r.live.size(), r.orphaned.size(), s.done, s.failed,
                    s.cancelled, s.converged, s.series_done, s.series);
      }
      if (std::any_of(running.begin(), running.end(), [](const auto& x) { return !x.second.orphaned.empty(); }))
        std::cout << "orphaned: marked running by a run or daemon that is gone; the next run or daemon adopts "
                     "(Slurm) or requeues them\n";
      if (detail) std::cout << '\n' << study_detail_text(*detail);
      if (id && !rows.empty()) {  // the method and what it was measured to cover
        const ExtrapolatorSettings e = study_extrapolation_settings(*store, *id);
        std::cout << "\nextrapolation: " << measured_coverage_line(e.method, e.expected_order.has_value()) << '\n';
      }
      if (id && !rows.empty()) {  // the outcome of every grid, counted (the report's stability map)
        const auto counts = stability_status(*store, *id)["counts"];
        std::string line;
        for (const auto& [outcome, n] : counts.items())
          // A grid's solver outcome "converged" is printed "solved": "converged" is a series' verdict.
          line += (line.empty() ? "" : ", ") + std::to_string(n.get<int>()) + " " +
                  (outcome == "converged" ? std::string("solved") : outcome);
        if (!line.empty()) std::cout << "\ngrids by outcome (stability): " << line << '\n';
      }
      if (!queue.empty()) {
        std::printf("\n%8s %-14s %-14s %-12s %s\n", "job", "grid", "slurm id", "state", "reason");
        for (const auto& j : queue)
          std::printf("%8lld %-14s %-14s %-12s %s\n", j.job_id, j.label.c_str(), j.external_id.substr(6).c_str(),
                      j.state.c_str(), j.reason.c_str());
      }
    }
    exit_code = to_int(ExitCode::kOk);
  });
}

void add_report_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("report", "rewrite a study's report from the database");
  auto name = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  auto out = std::make_shared<std::string>();
  sub->add_option("STUDY", *name, "study name")->required();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->add_option("--out", *out, "report folder (default reports/<study>)");
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    const long long id = require_study(*store, *name);
    finish_ready_series(*store, id);
    const std::filesystem::path dir = out->empty() ? std::filesystem::path("reports") / *name : std::filesystem::path(*out);
    StopSignals signals;  // SIGINT/SIGTERM stop the write (and a chart converter) at once
    try {
      const auto html = write_report(*store, id, dir, [&signals] { return signals.requested(); });
      std::cout << "report: " << html.string() << '\n';
      exit_code = to_int(ExitCode::kOk);
    } catch (const ReportInterrupted&) {
      std::cerr << "report: interrupted; run `gridfree report` again to write it\n";
      exit_code = to_int(ExitCode::kInterrupted);
    }
  });
}

void add_cancel_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("cancel", "cancel a study's queued jobs");
  auto name = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  sub->add_option("STUDY", *name, "study name")->required();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    const long long id = require_study(*store, *name);
    const StudyStatus before = store->statuses(id).front();
    exit_code = to_int(ExitCode::kOk);
    if (before.status == "cancelled") {
      std::cout << "study " << *name << " is already cancelled; nothing changed (submit again to resume)\n";
      return;
    }
    if (before.status != "queued" && before.status != "running") {
      std::cout << "study " << *name << " is already finished (" << before.status << "); nothing changed\n";
      return;
    }
    store->cancel(*name);
    const StudyStatus after = store->statuses(id).front();
    std::cout << "cancelled " << *name << ": " << (before.queued - after.queued) << " queued job(s) cancelled";
    if (after.running > 0) std::cout << ", " << after.running << " running job(s) finish";
    std::cout << " (submit again to resume)\n";
  });
}

}  // namespace gridfree::cli
