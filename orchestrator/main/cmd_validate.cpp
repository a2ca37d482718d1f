// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree validate STUDY  and  gridfree plan STUDY [--json] [-j N]
// [--target-rde X] [--db FILE]: read-only; nothing is written anywhere.
#include <algorithm>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "cmd_study.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "study/case_kind.h"
#include "study/case_vocabulary.h"
#include "study/grid_listing.h"
#include "extrap/grid_design.h"
#include "study/study_plan.h"
#include "sched/adaptive_prior.h"
#include "sched/cost_history.h"
#include "sched/external_target.h"
#include "store/sqlite.h"

namespace gridfree::cli {
namespace {

void warn_close_grids(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "warning: " << w << '\n';
}

// Grid-design warnings (extrap/grid_design.h) for every series; identical
// warnings of series that share their grids are listed once.
std::vector<std::string> grid_warnings(const Study& study, const ExpandedStudy& ex) {
  std::vector<std::string> out;
  std::map<std::size_t, std::vector<double>> h;
  for (const auto& j : ex.jobs) h[j.series].push_back(j.delta_star);
  if (study.adaptive_grids) {  // judged on the whole ladder; its coarse rungs stay in every fit
    for (auto& [series, grids] : h) {
      const auto ladder = study.external_ladders.find(ex.series[series].case_name);  // an external case's, in h
      grids = ladder != study.external_ladders.end() ? ladder->second.h_nominal : study.grid_delta_star;
    }
    if (!study.external() && study.adaptive_grids->coarsest_delta_star > kAsymptoticDeltaStar) {
      std::ostringstream w;
      w << "/grids/coarsest_delta_star " << study.adaptive_grids->coarsest_delta_star << " > " << kAsymptoticDeltaStar
        << ": the coarse rungs stay in every fit of the series and can keep it pre-asymptotic "
           "(docs/EXTRAPOLATION.md \"Adaptive series\")";
      out.push_back(w.str());
    }
  }
  for (const auto& [series, grids] : h)
    for (const auto& w : grid_design_warnings(grids, case_kind_id_of(study.definition) == CaseKindId::particle_bed))
      if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
  return out;
}

// "factorial", "one_at_a_time (baseline …)", or, when the series vary no
// factor (each case's quantities alone, as an external study without
// factors), the number of series: never a design that is not there.
std::string plan_heading(const Study& study, const ExpandedStudy& ex) {
  std::set<SeriesKey> without_quantity;
  std::set<std::string> cases;
  for (SeriesKey k : ex.series) {
    cases.insert(k.case_name);
    k.quantity.clear();
    without_quantity.insert(k);
  }
  if (without_quantity.size() > cases.size() || study.baseline) return study.design_description();
  return std::to_string(ex.series.size()) + " series (no factors)";
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("validate", "check a study file: every problem with its JSON path");
  auto file = std::make_shared<std::string>();
  sub->add_option("STUDY", *file, "study JSON file")->required();
  sub->callback([file, &exit_code] {
    const Study study = parse_study(*file);
    const ExpandedStudy ex = expand(study);
    warn_close_grids(neighbour_warnings(grid_listing(study)));
    warn_close_grids(grid_warnings(study, ex));
    std::cout << "ok: " << ex.series.size() << " series, " << (case_kind(study).job_serves_several_series() ? distinct_job_count(ex) : ex.jobs.size())
              << " jobs\n";
    exit_code = to_int(ExitCode::kOk);
  });
}

void add_plan_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("plan", "jobs, series, cells, estimated memory and time");
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto jobs = std::make_shared<int>(default_jobs());
  sub->add_option("STUDY", *file, "study JSON file")->required();
  sub->add_flag("--json", *json, "print the plan as JSON");
  sub->add_option("-j,--jobs", *jobs, "jobs at a time (for the wall-time estimate)");
  auto target = std::make_shared<double>(0);
  auto db = std::make_shared<std::string>(kDefaultDb);
  sub->add_option("--target-rde", *target,
                  "predict the grids a target RDE (fraction, 0.01 = 1 %) needs and their cost (default for "
                  "adaptive grids: their target_rde)")
      ->check(CLI::Range(1e-12, 0.999999));
  sub->add_option("--db", *db,
                  "database whose finished similar jobs calibrate the time estimates and whose finished similar "
                  "series inform --target-rde (only read)");
  sub->callback([file, json, jobs, target, db, &exit_code] {
    const Study study = parse_study(*file);
    const ExpandedStudy ex = expand(study);
    CostHistory history;
    try {
      history = read_cost_history(*db);
    } catch (const SqliteError& e) {
      throw InputError("--db", *db + " is not a readable gridfree database (" + e.what() + ")");
    }
    const Plan plan = make_plan(study, ex, std::max(1, *jobs), default_jobs(), history);
    const auto grids = grid_listing(study);
    const double rde = *target > 0 ? *target : study.adaptive_grids ? study.adaptive_grids->target_rde : 0;
    std::optional<TargetPlan> tp;
    std::optional<ExternalTargetPlan> etp;  // an external study's (sched/external_target.h)
    if (rde > 0 && study.external())
      etp = plan_external_target(study, ex, rde, *db, history);
    else if (rde > 0)
      tp = plan_for_target(study, rde, prior_rde_model(*db, study), history);
    // every warning, in the order printed on stderr, also in --json's "warnings"
    auto warnings = grid_warnings(study, ex);
    for (auto& w : neighbour_warnings(grids)) warnings.push_back(std::move(w));
    if (tp)
      for (auto& w : target_plan_warnings(*tp)) warnings.push_back(std::move(w));
    if (*json) {
      auto j = plan_to_json(plan);
      j["grids"] = grid_listing_json(grids);
      j["warnings"] = warnings;
      if (tp) j["target"] = target_plan_json(*tp);
      if (etp) j["target"] = external_target_json(*etp);
      std::cout << j.dump(2) << '\n';
    } else {
      std::cout << "study " << study.name << ": " << plan_heading(study, ex) << "\n" << plan_to_table(plan)
                << "\n" << grid_listing_table(grids);
      if (tp) std::cout << "\n" << target_plan_text(*tp);
      if (etp) std::cout << "\n" << external_target_text(*etp);
    }
    warn_close_grids(warnings);
    exit_code = to_int(ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
