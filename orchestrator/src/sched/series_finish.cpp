// SPDX-License-Identifier: GPL-3.0-or-later
// Series completion: extrapolation rows into the store; report data from the store.
#include "sched/series_finish.h"

#include "report/external_labels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include <spdlog/spdlog.h>

#include "core/version.h"
#include "extrap/self_check.h"
#include "extrap/value_format.h"
#include "extrap/verdict.h"
#include "report/report.h"
#include "report/series_coverage.h"
#include "sched/adaptive_series.h"
#include "sched/adaptive_window.h"
#include "store/store_alignment.h"
#include "store/store_beds.h"
#include "store/store_ensembles.h"
#include "report/series_vocabulary.h"
#include "study/adaptive_grids.h"
#include "study/case_kind.h"

namespace gridfree {
namespace {

std::optional<double> num(const nlohmann::json& j, const char* key) {
  if (!j.is_object()) return std::nullopt;
  auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  const double v = it->get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// The verdict object of the extrapolation JSON; a series whose extrapolation
// could not be made at all gets one from verdict_without_fit.
VerdictRow verdict_row(const nlohmann::json& ex, int n_converged) {
  if (ex.contains("verdict") && ex["verdict"].is_object() && ex["verdict"].contains("value") &&
      ex["verdict"]["value"].is_string()) {
    const auto& v = ex["verdict"];
    const nlohmann::json reasons = v.contains("reasons") && v["reasons"].is_array() ? v["reasons"] : nlohmann::json::array();
    return {v["value"].get<std::string>(), reasons.dump()};
  }
  const Verdict v = verdict_without_fit(n_converged, "the extrapolation failed: " + ex.value("status", std::string("?")));
  return {v.value, nlohmann::json(v.reasons).dump()};
}

// demote_if_flagged on the verdict object of the extrapolation JSON (h in any order).
void demote_flagged_json(const CoverageCheck& check, std::vector<double> h, nlohmann::json& ex,
                         const std::string& h_symbol) {
  if (!check.flagged() || h.empty() || !ex.contains("verdict") || !ex["verdict"].is_object() ||
      ex["verdict"].value("value", std::string()) != "converged")
    return;
  std::sort(h.begin(), h.end());
  Verdict v;
  v.value = "converged";
  demote_if_flagged(check, h, v, h_symbol);
  ex["verdict"]["value"] = v.value;
  ex["verdict"]["reasons"] = v.reasons;
  ex["verdict"]["next_h"] = v.next_h ? nlohmann::json(*v.next_h) : nlohmann::json(nullptr);
}

// "verdict converged: f0 = 1017.0 ± 1.5, finest f1 = 1015.9 ± 1.5 (RDE 0.15%)" — never "ok";
// the digits U supports (extrap/value_format.h), as the report prints them.
std::string verdict_log_text(const nlohmann::json& ex, const VerdictRow& verdict) {
  std::optional<double> f1, u, rde;
  if (ex.contains("grids") && ex["grids"].is_array() && !ex["grids"].empty()) {
    f1 = num(ex["grids"][0], "f");
    u = num(ex["grids"][0], "u");
    rde = num(ex["grids"][0], "rde");
  }
  // Each value with its own interval: f0 ± U₀, the finest grid's f₁ ± U₁.
  std::string out = verdict_line(verdict.value, num(ex, "f0"), num(ex, "u0"), f1, u, rde);
  const auto reasons = nlohmann::json::parse(verdict.reasons_json, nullptr, false);
  if (verdict.value != "converged" && reasons.is_array() && !reasons.empty() && reasons[0].is_string())
    out += "; " + reasons[0].get<std::string>();
  return out;
}

// Particle generator kind of every case of a study definition (a case that
// extends another takes its generator when it has none itself).
std::vector<std::string> generator_kinds(const nlohmann::json& def) {
  std::vector<std::string> out;
  if (!def.is_object() || !def.contains("cases") || !def["cases"].is_object()) return out;
  const auto& cases = def["cases"];
  for (const auto& [name, c] : cases.items()) {
    const nlohmann::json* k = &c;
    for (int depth = 0; depth < 8 && k->is_object(); ++depth) {
      const auto kind = k->value("/particles/generator/kind"_json_pointer, std::string());
      if (!kind.empty()) {
        out.push_back(kind);
        break;
      }
      if (!k->contains("extends") || !(*k)["extends"].is_string() || !cases.contains((*k)["extends"].get<std::string>()))
        break;
      k = &cases[(*k)["extends"].get<std::string>()];
    }
  }
  return out;
}

}  // namespace

ExtrapolatorSettings study_extrapolation_settings(Store& store, long long study_id) {
  ExtrapolatorSettings s;
  const auto def = store.study_definition(study_id);
  s.h_symbol = case_kind_of_definition(def).vocabulary().h_symbol;
  if (!def.is_object() || !def.contains("extrapolation")) return s;
  const auto& e = def["extrapolation"];
  if (e.contains("method") && e["method"].is_string()) s.method = e["method"].get<std::string>();
  if (e.contains("weights") && e["weights"].is_string()) s.weights = e["weights"].get<std::string>();
  if (e.contains("p_range") && e["p_range"].is_array() && e["p_range"].size() == 2) {
    s.p_low = e["p_range"][0].get<double>();
    s.p_high = e["p_range"][1].get<double>();
  }
  if (e.contains("expected_order") && e["expected_order"].is_number())
    s.expected_order = e["expected_order"].get<double>();
  return s;
}

std::string chosen_fit_name(const std::string& method) {
  if (method == "capped_power") return "capped";
  if (method.rfind("eh14_", 0) == 0) {  // eh14_<fit>_<weighting>
    const auto end = method.find('_', 5);
    return method.substr(5, end == std::string::npos ? std::string::npos : end - 5);
  }
  return method;  // power | mixed | constant
}

void extrapolation_rows(const nlohmann::json& ex, const std::vector<SeriesPoint>& points,
                        std::vector<ExtrapolationRow>& fits, std::vector<UncertaintyRow>& uncertainties) {
  const std::string status = ex.value("status", std::string("unknown"));
  const std::string method = ex.contains("method") && ex["method"].is_string() ? ex["method"].get<std::string>() : "";
  const nlohmann::json fit_obj = ex.contains("fits") && ex["fits"].is_object() ? ex["fits"] : nlohmann::json::object();
  // One row per fit the extrapolation reports (power and mixed always; capped,
  // first and second when made), `chosen` on the one f0 comes from; constant
  // data get a row of their own.
  const std::string chosen_fit = chosen_fit_name(method);
  std::vector<std::string> names = {"power", "mixed"};
  for (const char* extra : {"capped", "first", "second"})
    if (fit_obj.contains(extra)) names.push_back(extra);
  if (method == "constant") names.push_back("constant");
  for (const std::string& m : names) {
    ExtrapolationRow r;
    r.method = m;
    nlohmann::json f = fit_obj.contains(m) ? fit_obj[m] : nlohmann::json::object();
    if (m == "constant") f = {{"f0", ex.value("f0", nlohmann::json())}, {"sigma", 0.0}};
    r.f0 = num(f, "f0");
    r.p = num(f, "p");
    r.c = num(f, "c");
    r.c1 = num(f, "c1");
    r.c2 = num(f, "c2");
    r.sigma_re = num(f, "sigma");
    if (chosen_fit == m && num(ex, "sigma_re")) r.sigma_re = num(ex, "sigma_re");
    r.data_range = num(ex, "data_range");
    r.fs = num(ex, "fs");
    r.chosen = chosen_fit == m;
    // The chosen fit's row keeps U₀ as the extrapolation gave it (widened by
    // the averaged method and the bias checks), so `status` prints the f0 ± U₀
    // the report prints, not 1.25|f0 − f₁| + σ_RE recomputed.
    if (r.chosen && num(ex, "u0")) f["u0"] = *num(ex, "u0");
    r.status = status;
    if (m == "power" && f.contains("p_found") && f["p_found"].is_boolean() && !f["p_found"].get<bool>())
      r.status += " (p not found)";
    r.detail_json = f.dump();
    fits.push_back(std::move(r));
  }
  if (!ex.contains("grids") || !ex["grids"].is_array()) return;
  for (const auto& g : ex["grids"]) {
    const auto h = num(g, "h");
    if (!h) continue;
    for (const auto& p : points) {
      if (!p.dp_star || std::abs(p.delta_star - *h) > 1e-9 * std::max(1.0, std::abs(*h))) continue;
      uncertainties.push_back({p.job_id, p.delta_star, num(g, "f"), num(g, "u"), num(g, "rde")});
      break;
    }
  }
}

nlohmann::json finish_series(Store& store, const SeriesInfo& series, const Extrapolator& extrapolate) {
  const auto points = store.series_points(series.id);
  std::vector<double> h, f;
  for (const auto& p : points)
    if (p.result_status == "converged" && p.dp_star) {
      h.push_back(p.delta_star);
      f.push_back(*p.dp_star);
    }
  nlohmann::json ex;
  if (h.size() < 2) {
    ex = {{"status", "insufficient_grids"}, {"method", nullptr}};
  } else {
    try {
      ex = extrapolate(h, f);
    } catch (const std::exception& e) {
      ex = {{"status", std::string("error: ") + e.what()}};
    }
  }
  // The coverage self-check, once per finished series: reports read it. A
  // flagged check keeps the series from `converged`.
  std::optional<CoverageCheck> check;
  try {
    check = coverage_of(h, f, ex, extrapolate);
  } catch (const std::exception& e) {
    spdlog::warn("series {}: coverage self-check failed: {}", series.key.label(), e.what());
  }
  if (check)
    demote_flagged_json(*check, h, ex, case_kind(series.key).vocabulary().h_symbol);
  std::vector<ExtrapolationRow> fits;
  std::vector<UncertaintyRow> unc;
  extrapolation_rows(ex, points, fits, unc);
  const VerdictRow verdict = verdict_row(ex, static_cast<int>(h.size()));
  store.store_extrapolation(series.id, fits, unc, verdict);
  if (check) store.store_coverage(series.id, to_ordered_json(*check).dump());
  spdlog::info("series {} complete: {} converged of {}; {}", series.key.label(), h.size(), points.size(),
               verdict_log_text(ex, verdict));
  return ex;
}

int finish_ready_series(Store& store, long long study_id) {
  int finished = 0;
  advance_adaptive_series(store, study_id);  // adaptive series: refine or stop first
  const auto ready = store.series_ready(study_id);
  if (!ready.empty()) {
    Extrapolator extrapolate = library_extrapolator(study_extrapolation_settings(store, study_id));
    // An adaptive series stores the fit its last decision used: the window
    // of its finest grids when the coarse ones were left out.
    if (adaptive_grids_of(store.study_definition(study_id))) extrapolate = windowed_extrapolator(std::move(extrapolate));
    for (const auto& s : ready) {
      finish_series(store, s, extrapolate);
      ++finished;
    }
  }
  store.refresh_study_status(study_id);
  return finished;
}

int finish_series_of_job(Store& store, long long study_id, long long job_id, bool adaptive) {
  if (adaptive) return finish_ready_series(store, study_id);
  int finished = 0;
  const auto ready = store.series_ready_of_job(study_id, job_id);
  if (!ready.empty()) {
    const Extrapolator extrapolate = library_extrapolator(study_extrapolation_settings(store, study_id));
    for (const auto& s : ready) {
      finish_series(store, s, extrapolate);
      ++finished;
    }
  }
  store.refresh_study_status(study_id);
  return finished;
}

StudyReportData build_report_data(Store& store, long long study_id) {
  StudyReportData d;
  const auto st = store.statuses(study_id);
  if (!st.empty()) {
    d.study_name = st.front().name;
    d.status = st.front().status;
    d.submitted_at = st.front().submitted_at;
    d.finished_at = st.front().finished_at;
    d.baseline_description = st.front().design;
  }
  d.version = version_string();
  const auto settings = study_extrapolation_settings(store, study_id);
  d.extrapolation_method = settings.method;
  d.p_low = settings.p_low;
  d.p_high = settings.p_high;
  d.expected_order = settings.expected_order;
  const nlohmann::json definition = store.study_definition(study_id);
  d.generator_kinds = generator_kinds(definition);
  const nlohmann::json target = definition.value("/grids/target_rde"_json_pointer, nlohmann::json());
  if (target.is_number()) d.target_rde = target.get<double>();
  for (const auto& e : adaptive_events(store, study_id)) d.adaptive_decisions.push_back(e.message);
  d.ensembles = study_ensembles(store.db(), study_id);
  d.beds = case_beds(store.db(), study_id);
  for (const auto& s : store.series_of_study(study_id)) {
    SeriesData sd;
    sd.id = s.id;
    sd.case_name = s.key.case_name;
    sd.convection = s.key.convection;
    sd.drag = s.key.drag;
    sd.deposition = s.key.deposition;
    sd.fwhm_dp = s.key.fwhm_dp;
    sd.status = s.status;
    if (s.key.external()) label_external_series(definition, s.key, sd);
    if (!s.coverage_json.empty()) {
      const auto stored = nlohmann::json::parse(s.coverage_json, nullptr, false);
      if (stored.is_object()) sd.stored_coverage = coverage_from_json(stored);
    }
    for (const auto& p : store.series_points(s.id)) {
      GridPoint g;
      g.job_hash = p.job_hash;
      g.delta_star = p.delta_star;
      g.nx = p.cells[0];
      g.ny = p.cells[1];
      g.nz = p.cells[2];
      g.status = p.result_status.empty() ? p.job_status : p.result_status;
      g.dp_star = p.dp_star;
      g.reason = p.reason;
      g.wall_s = p.wall_s;
      g.cpu_s = p.cpu_s;
      g.peak_rss_mb = p.peak_rss_mb;
      g.iterations = p.iterations;
      g.worker_outcome = p.worker_outcome;
      g.remedy_from_iteration = p.remedy_from_iteration;
      sd.grids.push_back(std::move(g));
    }
    d.series.push_back(std::move(sd));
  }
  for (auto& a : alignment_values(store.db(), study_id))  // the alignment check, if the study ran it
    d.alignment.push_back({a.series_id, a.grid_index, a.delta_star, a.cells, std::move(a.dp_star)});
  return d;
}

std::filesystem::path write_report(Store& store, long long study_id, const std::filesystem::path& out_dir,
                                   const StopRequested& stop, ExtrapolationMemo* memo) {
  const StudyReportData data = build_report_data(store, study_id);
  Extrapolator extrapolate =
      library_extrapolator({data.extrapolation_method, data.p_low, data.p_high, "inverse_h", data.expected_order,
                            study_vocabulary(data.series).h_symbol});
  // Adaptive series: the report fits what the decisions and the store used,
  // the window of the finest grids (sched/adaptive_window.h).
  if (adaptive_grids_of(store.study_definition(study_id))) extrapolate = windowed_extrapolator(std::move(extrapolate));
  if (memo) extrapolate = memo->wrap(std::move(extrapolate));
  auto html = write_study_report(data, out_dir, extrapolate, stop).html;
  if (memo) memo->end_write();
  return html;
}

}  // namespace gridfree
