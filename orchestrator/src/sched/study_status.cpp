// SPDX-License-Identifier: GPL-3.0-or-later
// Inside view of one study for `gridfree status STUDY` (see study_status.h).
#include "sched/study_status.h"

#include <cmath>
#include <cstdio>

#include "exec/executor.h"
#include "extrap/fm_uncertainty.h"
#include "extrap/value_format.h"
#include "sched/study_eta.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

nlohmann::json opt(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::string cell(const nlohmann::json& v, const char* fmt) {
  if (!v.is_number()) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v.get<double>());
  return buf;
}

// The job document of a stored job (an empty object when unreadable).
nlohmann::json spec_of(Store& store, long long job_id) {
  auto st = store.db().prepare("SELECT spec_json FROM jobs WHERE id = ?");
  st.bind_all(job_id);
  if (!st.step()) return nlohmann::json::object();
  auto j = nlohmann::json::parse(st.as_text(0), nullptr, false);
  return j.is_object() ? j : nlohmann::json::object();
}

nlohmann::json series_row(Store& store, const SeriesInfo& s) {
  int done = 0, total = 0;
  for (const auto& p : store.series_points(s.id)) {
    ++total;
    if (p.job_status == "done" || p.job_status == "failed") ++done;
  }
  std::optional<double> f0, sigma_re, stored_u0;
  for (const auto& e : store.extrapolations(s.id))
    if (e.chosen) {
      f0 = e.f0;
      sigma_re = e.sigma_re;
      const auto detail = nlohmann::json::parse(e.detail_json, nullptr, false);
      if (detail.is_object() && detail.contains("u0") && detail["u0"].is_number()) stored_u0 = detail["u0"].get<double>();
    }
  std::optional<double> rde, f1, u1;
  double finest = INFINITY;
  for (const auto& u : store.uncertainties(s.id))
    if (u.delta_star < finest) {
      finest = u.delta_star;
      rde = u.rde;
      f1 = u.f;
      u1 = u.u;
    }
  // U₀ as the extrapolation gave it (stored with the chosen fit since
  // 2026-12-07); for older rows 1.25|f0 − f₁| + σ_RE from the stored f0, σ_RE
  // and finest value (docs/EXTRAPOLATION.md "U₀", before any widening).
  std::optional<double> u0 = stored_u0;
  if (!u0 && f0 && sigma_re && f1) u0 = extrapolated_value_uncertainty(*f0, *f1, *sigma_re);
  return {{"series", s.key.label()}, {"grids_done", done},  {"grids", total}, {"status", s.status},
          {"verdict", s.verdict.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.verdict)},
          {"f0", opt(f0)},           {"u0", opt(u0)},       {"f1", opt(f1)},  {"u1", opt(u1)},
          {"finest_rde", opt(rde)}};
}

}  // namespace

nlohmann::json study_detail(Store& store, long long study_id, const std::filesystem::path& runs_root, int workers) {
  nlohmann::json series = nlohmann::json::array(), running = nlohmann::json::array();
  std::vector<EtaJob> eta_jobs;
  int running_count = 0;
  for (const auto& s : store.series_of_study(study_id)) {
    series.push_back(series_row(store, s));
    const auto points = store.series_points(s.id);
    const auto spec = points.empty() ? nlohmann::json::object() : spec_of(store, points.front().job_id);
    for (const auto& p : points) {
      EtaJob e;
      e.model_s = estimated_seconds(p.cells, 1, apriori_cost_ratio(spec, p.cells).ratio);
      if (p.job_status == "done" || p.job_status == "failed") {
        e.state = EtaJob::State::kDone;
        e.wall_s = p.wall_s;
      } else if (p.job_status == "running") {
        ++running_count;
        e.state = EtaJob::State::kRunning;
        const auto dir = run_dir_for(runs_root, p.job_hash);
        const auto prog = read_job_progress(progress_file(dir));
        if (prog && (*prog)["elapsed_s"].is_number()) e.elapsed_s = (*prog)["elapsed_s"].get<double>();
        nlohmann::json r = {{"job", p.job_id},
                            {"series", s.key.label()},
                            {"delta_star", p.delta_star},
                            {"cells", {p.cells[0], p.cells[1], p.cells[2]}},
                            {"log", (dir / "worker.log").string()}};
        for (const char* k : {"iteration", "continuity", "momentum", "dp_star", "elapsed_s"})
          r[k] = prog && prog->contains(k) ? (*prog)[k] : nlohmann::json(nullptr);
        running.push_back(r);
      } else if (p.job_status == "cancelled") {
        continue;
      }
      eta_jobs.push_back(e);
    }
  }
  const Eta eta = estimate_eta(eta_jobs, workers > 0 ? workers : std::max(1, running_count));
  return {{"series", series},
          {"running", running},
          {"eta", {{"seconds", eta.eta_s}, {"text", hours_minutes(eta.eta_s)}, {"model_scale", eta.scale}}}};
}

std::string study_detail_text(const nlohmann::json& d) {
  std::string out;
  char line[512];
  // f0 ± U₀ and the finest grid's f₁ ± U₁ with the digits U supports
  // (extrap/value_format.h), as the report prints them.
  const auto value = [](const nlohmann::json& j) {
    return j.is_number() ? std::optional<double>(j.get<double>()) : std::nullopt;
  };
  std::snprintf(line, sizeof line, "%-34s %-10s %-16s %-22s %-22s %9s\n", "series", "grids done", "verdict",
                "f0 ± U0", "finest f1 ± U1", "RDE fine");
  out += line;
  for (const auto& s : d["series"]) {
    const std::string grids = std::to_string(s["grids_done"].get<int>()) + "/" + std::to_string(s["grids"].get<int>());
    const std::string verdict = s["verdict"].is_string() ? s["verdict"].get<std::string>() : "(" + s["status"].get<std::string>() + ")";
    const std::string rde = s["finest_rde"].is_number() ? format_percent_fixed(s["finest_rde"].get<double>()) : "-";
    const auto f0 = value(s.value("f0", nlohmann::json())), f1 = value(s.value("f1", nlohmann::json()));
    const auto u0 = value(s.value("u0", nlohmann::json())), u1 = value(s.value("u1", nlohmann::json()));
    const std::string f0_text = f0 ? format_value_u(*f0, u0) : "-";
    const std::string f1_text = f1 ? format_value_u(*f1, u1) : "-";
    std::snprintf(line, sizeof line, "%-34s %-10s %-16s %-22s %-22s %9s\n", s["series"].get<std::string>().c_str(),
                  grids.c_str(), verdict.c_str(), f0_text.c_str(), f1_text.c_str(), rde.c_str());
    out += line;
  }
  if (!d["running"].empty()) {
    out += "\nrunning jobs\n";
    std::snprintf(line, sizeof line, "%-34s %7s %-14s %9s %10s %10s %12s %9s  %s\n", "series", "Δ*", "cells",
                  "iteration", "continuity", "momentum", "dp*", "elapsed", "log");
    out += line;
    for (const auto& r : d["running"]) {
      const auto& c = r["cells"];
      const std::string cells = std::to_string(c[0].get<int>()) + "x" + std::to_string(c[1].get<int>()) + "x" +
                                std::to_string(c[2].get<int>());
      const std::string elapsed = cell(r["elapsed_s"], "%.0f s");
      std::snprintf(line, sizeof line, "%-34s %7s %-14s %9s %10s %10s %12s %9s  %s\n",
                    r["series"].get<std::string>().c_str(), cell(r["delta_star"], "%.4g").c_str(), cells.c_str(),
                    cell(r["iteration"], "%.0f").c_str(), cell(r["continuity"], "%.2e").c_str(),
                    cell(r["momentum"], "%.2e").c_str(), cell(r["dp_star"], "%.6g").c_str(), elapsed.c_str(),
                    r["log"].get<std::string>().c_str());
      out += line;
    }
  }
  // No ETA (null): nobody works on the study now (gridfree status).
  if (!d["eta"]["seconds"].is_number())
    return out + (d["running"].empty() ? "\nno ETA: no run or daemon works on this study now\n" : "");
  if (d["running"].empty() && d["eta"]["seconds"].get<double>() <= 0) return out + "\nnothing left to run\n";
  out += "\nETA " + d["eta"]["text"].get<std::string>() + " (cost model × " + cell(d["eta"]["model_scale"], "%.2g") +
         " from the finished jobs)\n";
  return out;
}

}  // namespace gridfree
