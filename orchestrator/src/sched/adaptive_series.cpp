// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive series decisions in the store (sched/adaptive_series.h).
#include "sched/adaptive_series.h"

#include <cmath>
#include <limits>

#include <spdlog/spdlog.h>

#include "job/job_hash.h"
#include "report/extrapolator.h"
#include "sched/adaptive_window.h"
#include "sched/series_finish.h"
#include "study/case_kind.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

std::optional<double> number(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  const double v = j[key].get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::string adaptive_status(Store& store, long long series_id) {
  auto st = store.db().prepare("SELECT COALESCE(adaptive_status, '') FROM series WHERE id = ?");
  st.bind_all(series_id);
  return st.step() ? st.as_text(0) : "";
}

// Links and unfinished jobs of a series, read inside the deciding transaction.
std::pair<long long, long long> link_counts(Store& store, long long series_id) {
  auto st = store.db().prepare(
      "SELECT COUNT(*), COALESCE(SUM(j.status IN ('queued','running')), 0) FROM study_jobs sj "
      "JOIN jobs j ON j.id = sj.job_id WHERE sj.series_id = ?");
  st.bind_all(series_id);
  st.step();
  return {st.as_int(0), st.as_int(1)};
}

nlohmann::json job_spec(Store& store, long long job_id) {
  auto st = store.db().prepare("SELECT spec_json FROM jobs WHERE id = ?");
  st.bind_all(job_id);
  return st.step() ? nlohmann::json::parse(st.as_text(0)) : nlohmann::json();
}

// Links the job `spec` of `rung` to the series (the job row is shared when
// another study has it already). Inside a transaction.
long long link_rung(Store& store, const SeriesInfo& s, const nlohmann::json& spec, const AdaptiveRung& rung,
                    std::size_t index, double actual_delta_star) {
  auto& db = store.db();
  const std::string hash = job_hash(spec);
  const long long cells = static_cast<long long>(rung.cells[0]) * rung.cells[1] * rung.cells[2];
  db.prepare("INSERT OR IGNORE INTO jobs(job_hash, spec_json, nx, ny, nz, cells, delta_star) VALUES (?, ?, ?, ?, ?, ?, ?)")
      .bind_all(hash, spec.dump(), rung.cells[0], rung.cells[1], rung.cells[2], cells, actual_delta_star)
      .run();
  auto find = db.prepare("SELECT id FROM jobs WHERE job_hash = ?");
  find.bind_all(hash);
  find.step();
  const long long job_id = find.as_int(0);
  db.prepare("UPDATE jobs SET status = 'queued', error = NULL WHERE id = ? AND status = 'cancelled'").bind_all(job_id).run();
  db.prepare("INSERT OR IGNORE INTO study_jobs(study_id, job_id, series_id, grid_index, delta_star_nominal) "
             "VALUES (?, ?, ?, ?, ?)")
      .bind_all(s.study_id, job_id, s.id, static_cast<long long>(index), rung.delta_star)
      .run();
  return job_id;
}

// One decision for one ready series; true when one was written.
bool decide_series(Store& store, const SeriesInfo& s, const AdaptiveGrids& settings, const Extrapolator& extrapolate) {
  const std::string status = adaptive_status(store, s.id);
  if (status == "target_met" || status == "target_not_reached") return false;
  const auto points = store.series_points(s.id);
  if (points.empty()) return false;
  std::vector<double> h, f;
  double measured = 0, model = 0;
  for (const auto& p : points) {
    if (p.result_status == "converged" && p.dp_star) {
      h.push_back(p.delta_star);
      f.push_back(*p.dp_star);
    }
    if (p.cpu_s > 0) {
      measured += p.cpu_s;
      model += estimated_seconds(p.cells, 1);
    }
  }
  nlohmann::json ex;
  std::string window;
  if (h.size() >= 2) {
    try {
      WindowedFit w = windowed_extrapolation(h, f, extrapolate);  // the finest grids when the coarse spoil the fit
      ex = std::move(w.extrapolation);
      // The cell size in the case's own symbol (study/case_vocabulary.h).
      window = window_sentence(w, case_kind(s.key).vocabulary().h_symbol);
    } catch (const std::exception& e) {
      ex = {{"status", std::string("error: ") + e.what()}};
    }
  }
  AdaptiveFit fit = adaptive_fit_of(ex, static_cast<int>(h.size()));
  fit.window = window;
  const nlohmann::json spec = job_spec(store, points.front().job_id);
  CostHistory own;  // the series' finished jobs: what an undeclared external cost is fitted to
  for (const auto& p : points)
    if (p.cpu_s > 0)
      own[cost_similarity_key(spec)].push_back({static_cast<double>(p.cells[0]) * p.cells[1] * p.cells[2], p.cpu_s});
  const KindLadder kl =
      case_kind(s.key).adaptive_ladder(store.study_definition(s.study_id), settings, s.key, spec, own);
  const std::vector<AdaptiveRung>& ladder = kl.rungs;
  const double scale = kl.scale_by_measured && measured > 0 && model > 0 ? measured / model : 1.0;
  const auto decision = decide_adaptive_step(settings, ladder, points.size(), fit, scale,
                                             static_cast<double>(physical_memory_bytes()));

  Transaction tx(store.db());
  const auto [links, unfinished] = link_counts(store, s.id);
  if (links != static_cast<long long>(points.size()) || unfinished != 0 || adaptive_status(store, s.id) != status)
    return false;  // another process decided first
  std::optional<long long> job_id;
  if (decision.kind == AdaptiveDecision::Kind::kContinue) {
    const std::size_t k = decision.next_rung;
    job_id = link_rung(store, s, kl.specs[k], ladder[k], k, kl.h[k]);
  }
  store.db()
      .prepare("UPDATE series SET adaptive_status = ?, adaptive_note = ? WHERE id = ?")
      .bind_all(adaptive_status_word(decision.kind), decision.message, s.id)
      .run();
  const std::string message = s.key.label() + ": " + decision.message;
  store.log_event(s.study_id, job_id, "adaptive", message);
  tx.commit();
  spdlog::info("{}", message);
  return true;
}

}  // namespace

AdaptiveFit adaptive_fit_of(const nlohmann::json& ex, int ng) {
  AdaptiveFit fit;
  fit.ng = ng;
  if (!ex.is_object()) return fit;
  if (ex.contains("verdict") && ex["verdict"].is_object() && ex["verdict"].contains("value") &&
      ex["verdict"]["value"].is_string())
    fit.verdict = ex["verdict"]["value"].get<std::string>();
  fit.f0 = number(ex, "f0");
  if (!ex.contains("grids") || !ex["grids"].is_array()) return fit;
  double finest = std::numeric_limits<double>::infinity();
  for (const auto& g : ex["grids"]) {
    const auto h = number(g, "h");
    if (!h || *h >= finest) continue;
    finest = *h;
    fit.finest_delta_star = h;
    fit.finest_rde = number(g, "rde");
    fit.finest_u = number(g, "u");
  }
  return fit;
}

int advance_adaptive_series(Store& store, long long study_id) {
  const auto settings = adaptive_grids_of(store.study_definition(study_id));
  if (!settings) return 0;
  const auto extrapolate = library_extrapolator(study_extrapolation_settings(store, study_id));
  int decisions = 0;
  // A continue whose job is done already (reused) leaves the series ready:
  // decide again until every series waits for a job or has stopped.
  for (bool again = true; again;) {
    again = false;
    for (const auto& s : store.series_ready(study_id))
      if (decide_series(store, s, *settings, extrapolate)) {
        ++decisions;
        again = true;
      }
  }
  return decisions;
}

std::vector<AdaptiveEvent> adaptive_events(Store& store, long long study_id) {
  std::vector<AdaptiveEvent> out;
  auto st = store.db().prepare("SELECT at, COALESCE(message, '') FROM events WHERE study_id = ? AND kind = 'adaptive' ORDER BY id");
  st.bind_all(study_id);
  while (st.step()) out.push_back({st.as_text(0), st.as_text(1)});
  return out;
}

}  // namespace gridfree
