// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree's own case, a particle bed solved by gridfree-worker
// (study/case_kind.h): factors convection, fwhm_dp, drag and deposition,
// one series per configuration (its quantity dp*), grids in Δ*.
#include <cstdio>

#include "study/case_kind.h"

namespace gridfree {
namespace {

std::array<double, 3> domain_of(const nlohmann::json& spec) {
  std::array<double, 3> domain{};
  const auto d = spec.value("/case/domain_dp"_json_pointer, nlohmann::json::array());
  for (std::size_t a = 0; a < 3 && a < d.size(); ++a) domain[a] = d[a].get<double>();
  return domain;
}

class ParticleBedKind final : public CaseKind {
 public:
  std::string name() const override { return "particle_bed"; }
  CaseKindId id() const override { return CaseKindId::particle_bed; }

  // "PC1 superbee fwhm6 bvk 9x61x3".
  std::string job_label(const std::string& series_label, const nlohmann::json& /*spec*/,
                        const std::array<int, 3>& cells) const override {
    char text[64];
    std::snprintf(text, sizeof text, " %dx%dx%d", cells[0], cells[1], cells[2]);
    return series_label + text;
  }

  // "<study>/<series label> d*=<Δ*>" (the label without its cells).
  std::string job_name(const std::string& study_name, const std::string& label, double delta_star,
                       const nlohmann::json& /*spec*/) const override {
    char d[32];
    std::snprintf(d, sizeof d, "%g", delta_star);
    return study_name + "/" + label.substr(0, label.rfind(' ')) + " d*=" + d;
  }

  bool job_serves_several_series() const override { return false; }
  bool jobs_follow_outside_files() const override { return false; }
  bool has_bed_columns() const override { return true; }
  bool cores_are_tasks() const override { return false; }
  bool results_recollectable() const override { return false; }  // the worker writes its result

  // The worker's result document has its cells and no collect section.
  void take_result(const nlohmann::json& /*spec*/, const std::array<int, 3>& /*job_cells*/,
                   std::string& /*result_json*/, std::array<int, 3>& /*result_cells*/) const override {}

  // gridfree's own model (study/cost_model.h, job/memory_estimate.h).
  std::optional<ExternalJobCost> own_cost(const nlohmann::json& /*spec*/, const std::array<int, 3>& /*cells*/,
                                          const std::map<std::string, DeclaredCost>& /*declared*/,
                                          const CostHistory& /*history*/) const override {
    return std::nullopt;
  }

  Plan plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
            const CostHistory& history) const override {
    return make_particle_bed_plan(study, expanded, workers, cores, history);
  }

  // The ladder in Δ* (study/adaptive_grids.h); each rung's job is the first
  // job on the rung's cells; its cost is the model's, scaled by the series' measurements.
  KindLadder adaptive_ladder(const nlohmann::json& /*definition*/, const AdaptiveGrids& settings,
                             const SeriesKey& /*key*/, const nlohmann::json& first_spec,
                             const CostHistory& /*measured*/) const override {
    KindLadder out;
    const auto domain = domain_of(first_spec);
    out.rungs = adaptive_rungs(gridfree::adaptive_ladder(settings), domain);
    for (const auto& rung : out.rungs) {
      nlohmann::json spec = first_spec;
      spec["numerics"]["grid"] = {{"cells", {rung.cells[0], rung.cells[1], rung.cells[2]}}};
      out.specs.push_back(std::move(spec));
      out.h.push_back(delta_star_of(domain, rung.cells));
    }
    return out;
  }
};

}  // namespace

const CaseKind& particle_bed_kind() {
  static const ParticleBedKind kind;
  return kind;
}

}  // namespace gridfree
