// SPDX-License-Identifier: GPL-3.0-or-later
// A user's code run from a template (study/case_kind.h, docs/EXTERNAL.md):
// the study's own factors are placeholders, one job per (case × levels ×
// grid) serves every quantity, grids in the case's declared h.
#include <cstdio>

#include "study/case_kind.h"
#include "study/external_intake.h"
#include "study/external_plan.h"
#include "study/external_rungs.h"

namespace gridfree {
namespace {

// " scheme=QUICK tol=1e-6": the job's factor levels, in the document's order.
std::string levels_text(const nlohmann::json& spec) {
  std::string out;
  const auto at = nlohmann::json::json_pointer("/case/external/levels");
  if (spec.contains(at) && spec.at(at).is_object())
    for (const auto& [name, level] : spec.at(at).items())
      if (level.is_string()) out += " " + name + "=" + level.get<std::string>();
  return out;
}

// " h=0.125".
std::string h_text(const nlohmann::json& spec) {
  char h[48];
  std::snprintf(h, sizeof h, " h=%g", spec.value("/numerics/grid/h"_json_pointer, 0.0));
  return h;
}

class ExternalKind final : public CaseKind {
 public:
  std::string name() const override { return "external"; }
  CaseKindId id() const override { return CaseKindId::external; }

  // "cavity scheme=QUICK h=0.125": the case, its levels and its grid (one
  // job serves every quantity, so no series' label names it).
  std::string job_label(const std::string& series_label, const nlohmann::json& spec,
                        const std::array<int, 3>& /*cells*/) const override {
    const std::string case_name = spec.contains("case") && spec["case"].is_object()
                                      ? spec["case"].value("name", series_label)
                                      : series_label;
    return case_name + levels_text(spec) + h_text(spec);
  }

  // "<study>/<case> <levels> <quantities> h=<h>".
  std::string job_name(const std::string& study_name, const std::string& /*label*/, double /*delta_star*/,
                       const nlohmann::json& spec) const override {
    std::string quantities;
    const auto q = nlohmann::json::json_pointer("/case/external/collect/quantities");
    if (spec.contains(q) && spec.at(q).is_object())
      for (const auto& [name, ignored] : spec.at(q).items()) quantities += (quantities.empty() ? " " : ",") + name;
    const std::string case_name =
        spec.contains("case") && spec["case"].is_object() ? spec["case"].value("name", "") : "";
    return study_name + "/" + case_name + levels_text(spec) + quantities + h_text(spec);
  }

  bool job_serves_several_series() const override { return true; }
  bool jobs_follow_outside_files() const override { return true; }
  bool has_bed_columns() const override { return false; }
  bool cores_are_tasks() const override { return true; }
  bool results_recollectable() const override { return true; }

  // The collect section the quantities were read with (study/external_intake.h)
  // and the job's cells (the code does not report them), so the measured
  // cost history has its cell counts.
  void take_result(const nlohmann::json& spec, const std::array<int, 3>& job_cells, std::string& result_json,
                   std::array<int, 3>& result_cells) const override {
    record_collect_spec(spec, result_json);
    if (result_cells == std::array<int, 3>{}) result_cells = job_cells;
  }

  // Declared figures, else the case's measured history, else unknown
  // (study/external_cost.h): never gridfree's solver model.
  std::optional<ExternalJobCost> own_cost(const nlohmann::json& spec, const std::array<int, 3>& cells,
                                          const std::map<std::string, DeclaredCost>& declared,
                                          const CostHistory& history) const override {
    const std::string case_name =
        spec.contains("case") && spec["case"].is_object() ? spec["case"].value("name", "") : "";
    const auto d = declared.find(case_name);
    const auto h = history.find(cost_similarity_key(spec));
    const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
    return external_job_estimate(d == declared.end() ? std::nullopt : d->second.cpu_s_per_cell,
                                 d == declared.end() ? std::nullopt : d->second.mb_per_cell,
                                 h == history.end() ? nullptr : &h->second, n);
  }

  Plan plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
            const CostHistory& history) const override {
    return make_external_plan(study, expanded, workers, cores, history);
  }

  // The ladder in h of the case's grid variable (study/external_rungs.h),
  // its costs the external estimate itself.
  KindLadder adaptive_ladder(const nlohmann::json& definition, const AdaptiveGrids& settings, const SeriesKey& key,
                             const nlohmann::json& first_spec, const CostHistory& measured) const override {
    ExternalRungs r = external_rungs(definition, settings, key.case_name, first_spec, measured);
    KindLadder out;
    out.rungs = std::move(r.rungs);
    out.specs = std::move(r.specs);
    out.h = std::move(r.h);
    out.scale_by_measured = false;
    return out;
  }
};

}  // namespace

const CaseKind& external_kind() {
  static const ExternalKind kind;
  return kind;
}

}  // namespace gridfree
