// SPDX-License-Identifier: GPL-3.0-or-later
// parse_study: a study file → Study, after the schema (schemas/study.schema.json)
// and the semantic checks of docs/INTERFACE.md §3/§4. Every problem is collected
// with its JSON pointer before one InputError is thrown.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <variant>

#include "core/input_error.h"
#include "core/json_fields.h"
#include "core/follow_on_problems.h"
#include "study/study_cores.h"
#include "study/format_number.h"
#include "study/grid_listing.h"
#include "core/schema_validation.h"
#include "drag/drag_law.h"
#include "grid/grid.h"
#include "job/job_spec.h"
#include "particles/particle_io.h"
#include "schemes/limiter.h"
#include "study/case_extends.h"
#include "study/external_factors.h"
#include "study/slurm_block.h"
#include "study/design_baseline.h"
#include "study/study.h"
#include "study/study_alignment.h"
#include "study/study_plan.h"
#include "study/study_transfer.h"

namespace gridfree {
namespace {

using nlohmann::json;


bool is_number(const json& j) { return j.is_number() && !j.is_boolean(); }

// Checks parse_case may or may not make; each reported once per pointer.
void check_case_physics(const json& c, const std::string& at, const std::filesystem::path& base_dir,
                        ProblemList& problems) {
  if (!c.is_object()) return;
  if (auto g = c.find("gas"); g != c.end() && g->is_object()) {
    if (auto mu = g->find("viscosity_g_cm_s"); mu != g->end() && is_number(*mu) && mu->get<double>() <= 0)
      problems.add_once(at + "/gas/viscosity_g_cm_s", "gas viscosity must be positive");
    if (auto rho = g->find("density_g_cm3"); rho != g->end() && is_number(*rho) && rho->get<double>() <= 0)
      problems.add_once(at + "/gas/density_g_cm3", "gas density must be positive");
  }
  if (auto b = c.find("boundaries"); b != c.end() && b->is_object()) {
    for (const char* side : {"y_low", "y_high"}) {
      auto s = b->find(side);
      if (s == b->end() || !s->is_object()) continue;
      auto u = s->find("superficial_velocity_cm_s");
      if (u != s->end() && is_number(*u) && u->get<double>() < 0)
        problems.add_once(at + "/boundaries/" + side + "/superficial_velocity_cm_s",
                 "inflow velocity must not be negative");
    }
  }
  double ly = -1;
  if (auto d = c.find("domain_dp"); d != c.end() && d->is_array()) {
    for (std::size_t a = 0; a < d->size(); ++a) {
      const auto& v = (*d)[a];
      if (is_number(v) && v.get<double>() <= 0)
        problems.add_once(at + "/domain_dp/" + std::to_string(a), "domain size must be positive");
    }
    if (d->size() == 3 && is_number((*d)[1])) ly = (*d)[1].get<double>();
  }
  if (auto p = c.find("probes"); p != c.end() && p->is_object() && ly > 0) {
    if (auto dp = p->find("pressure_drop"); dp != p->end() && dp->is_object()) {
      for (const char* key : {"y1_dp", "y2_dp"}) {
        auto y = dp->find(key);
        if (y == dp->end() || !is_number(*y)) continue;
        const double v = y->get<double>();
        if (v <= 0 || v >= ly)
          problems.add_once(at + "/probes/pressure_drop/" + key,
                   "probe at y* = " + y->dump() + " is outside the domain (0, " + json(ly).dump() + ")");
      }
    }
  }
  if (auto parts = c.find("particles"); parts != c.end() && parts->is_object()) {
    if (auto f = parts->find("file"); f != parts->end() && f->is_string()) {
      std::filesystem::path path = f->get<std::string>();
      if (path.is_relative()) path = base_dir / path;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec))
        problems.add_once(at + "/particles/file", "particle file '" + f->get<std::string>() + "' not found");
    }
  }
}

std::vector<std::string> string_levels(const json& f, const std::string& at, ProblemList& problems) {
  std::vector<std::string> out;
  if (!f.is_array()) {
    problems.add_once(at, "must be an array of names");
    return out;
  }
  if (f.empty()) problems.add_once(at, "a factor needs at least one level");
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!f[i].is_string()) {
      problems.add_once(at + "/" + std::to_string(i), "must be a string");
      continue;
    }
    auto name = f[i].get<std::string>();
    if (std::find(out.begin(), out.end(), name) != out.end())
      problems.add_once(at + "/" + std::to_string(i), "level '" + name + "' is listed twice");
    out.push_back(name);
  }
  return out;
}

void check_names(const std::vector<std::string>& levels, const std::string& at, ProblemList& problems,
                 bool (*known)(const std::string&), const std::string& valid) {
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (!known(levels[i]))
      problems.add_once(at + "/" + std::to_string(i), "unknown '" + levels[i] + "'; valid: " + valid);
}

bool known_convection(const std::string& n) { return limiter_from_name(n).has_value(); }
bool known_drag(const std::string& n) { return drag_law_from_name(n).has_value(); }

void parse_factors(const json& doc, Study& s, ProblemList& problems) {
  auto f = doc.find("factors");
  if (f == doc.end()) return;
  if (!f->is_object()) {
    problems.add_once("/factors", "must be an object");
    return;
  }
  for (auto it = f->begin(); it != f->end(); ++it) {
    const std::string at = child_pointer("/factors", it.key());
    if (it.key() == "convection") {
      s.factors.convection = string_levels(*it, at, problems);
      check_names(s.factors.convection, at, problems, known_convection, limiter_names());
    } else if (it.key() == "drag") {
      s.factors.drag = string_levels(*it, at, problems);
      check_names(s.factors.drag, at, problems, known_drag, drag_law_names());
    } else if (it.key() == "deposition") {
      parse_deposition_levels(*it, at, s, problems);  // names or transfer objects (study_transfer.cpp)
    } else if (it.key() == "fwhm_dp") {
      if (!it->is_array()) {
        problems.add_once(at, "must be an array of numbers");
        continue;
      }
      if (it->empty()) problems.add_once(at, "a factor needs at least one level");
      for (std::size_t i = 0; i < it->size(); ++i) {
        const auto& v = (*it)[i];
        if (!is_number(v) || v.get<double>() <= 0) {
          problems.add_once(at + "/" + std::to_string(i), "filter width must be a positive number");
          continue;
        }
        const double w = v.get<double>();
        if (std::find(s.factors.fwhm_dp.begin(), s.factors.fwhm_dp.end(), w) != s.factors.fwhm_dp.end())
          problems.add_once(at + "/" + std::to_string(i), "level listed twice");
        s.factors.fwhm_dp.push_back(w);
      }
    } else {
      problems.add_once(at, "unknown factor; valid: convection, fwhm_dp, drag, deposition");
    }
  }
}

// A factor left out has one level, its documented default (the paper's
// baseline; docs/INTERFACE.md section 3): superbee, fwhm_dp 6, bvk, diffusion.
void default_factors(Study& s) {
  if (s.factors.convection.empty()) s.factors.convection = {"superbee"};
  if (s.factors.drag.empty()) s.factors.drag = {"bvk"};
  if (s.factors.deposition.empty()) s.factors.deposition = {"diffusion"};
  if (s.factors.fwhm_dp.empty()) s.factors.fwhm_dp = {6.0};
}

template <class T>
bool contains(const std::vector<T>& v, const T& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

void parse_design(const json& doc, Study& s, ProblemList& problems) {
  const json* baseline = one_at_a_time_baseline(doc, problems);
  if (baseline == nullptr) return;
  const json& b = *baseline;
  const std::string at = "/design/one_at_a_time";
  SeriesKey key;
  key.case_name = s.cases.empty() ? "" : s.cases.front().name;
  key.convection = s.factors.convection.front();
  key.drag = s.factors.drag.front();
  key.deposition = s.factors.deposition.front();
  key.fwhm_dp = s.factors.fwhm_dp.front();
  for (auto it = b.begin(); it != b.end(); ++it) {
    const std::string where = child_pointer(at, it.key());
    const std::string& k = it.key();
    if (k == "fwhm_dp") {
      if (!is_number(*it)) {
        problems.add_once(where, "must be a number");
        continue;
      }
      key.fwhm_dp = it->get<double>();
      if (!contains(s.factors.fwhm_dp, key.fwhm_dp))
        problems.add_once(where, "baseline fwhm_dp " + it->dump() + " is not a level of /factors/fwhm_dp");
      continue;
    }
    if (!it->is_string()) {
      problems.add_once(where, "must be a string");
      continue;
    }
    const std::string v = it->get<std::string>();
    if (k == "case") {
      key.case_name = v;
      if (s.find_case(v) == nullptr) problems.add_once(where, "unknown case '" + v + "' (not in /cases)");
    } else if (k == "convection" || k == "drag" || k == "deposition") {
      const auto& levels = k == "convection" ? s.factors.convection
                           : k == "drag"     ? s.factors.drag
                                             : s.factors.deposition;
      (k == "convection" ? key.convection : k == "drag" ? key.drag : key.deposition) = v;
      if (!contains(levels, v))
        problems.add_once(where, "baseline " + k + " '" + v + "' is not a level of /factors/" + k);
    } else {
      problems.add_once(where, "unknown baseline field; valid: case, convection, fwhm_dp, drag, deposition");
    }
  }
  s.baseline = key;
}

void parse_grids(const json& doc, Study& s, ProblemList& problems) {
  auto g = doc.find("grids");
  if (g == doc.end() || !g->is_object()) {
    problems.add_once("/grids", "required: {\"delta_star\": [...]} or {\"cells\": [[nx,ny,nz], ...]}");
    return;
  }
  if (g->contains("target_rde")) {  // adaptive series (study/adaptive_grids.h)
    if ((s.adaptive_grids = parse_adaptive_grids(*g, problems))) s.grid_delta_star = adaptive_ladder(*s.adaptive_grids);
    return;
  }
  if (g->contains("variables")) {  // external cases (study/external_case.h)
    const json& v = (*g)["variables"];
    if (!v.is_object() || v.empty()) {
      problems.add_once("/grids/variables", "must name at least one grid variable with its values");
      return;
    }
    std::size_t length = 0;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string at = child_pointer("/grids/variables", it.key());
      const bool name_ok = !it.key().empty() && (std::isalpha(static_cast<unsigned char>(it.key()[0])) || it.key()[0] == '_') &&
                           std::all_of(it.key().begin(), it.key().end(), [](char ch) {
                             return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                           });
      if (!name_ok) {
        problems.add_once(at, "a variable name is a letter or '_' followed by letters, digits or '_'");
        continue;
      }
      if (!it->is_array() || it->empty()) {
        problems.add_once(at, "must be a non-empty array of numbers, one per grid");
        continue;
      }
      std::vector<double> values;
      for (std::size_t i = 0; i < it->size(); ++i) {
        if (!is_number((*it)[i]) || !std::isfinite((*it)[i].get<double>())) {
          problems.add_once(at + "/" + std::to_string(i), "must be a finite number");
          continue;
        }
        values.push_back((*it)[i].get<double>());
      }
      if (values.size() == it->size()) s.grid_variables[it.key()] = std::move(values);
      length = std::max(length, it->size());
    }
    std::string lengths;
    bool uneven = false;
    for (auto it = v.begin(); it != v.end(); ++it) {
      lengths += (lengths.empty() ? "" : ", ") + it.key() + " " + std::to_string(it->is_array() ? it->size() : 0);
      uneven = uneven || !it->is_array() || it->size() != length;
    }
    if (uneven) {
      problems.add_once("/grids/variables", "the grid variables have different lengths (" + lengths +
                                                "); each needs one value per grid");
      s.grid_variables.clear();
    }
    return;
  }
  const bool ds = g->contains("delta_star"), cs = g->contains("cells");
  if (ds == cs) {
    problems.add_once("/grids", "give exactly one of delta_star and cells");
    return;
  }
  if (ds) {
    const json& a = (*g)["delta_star"];
    if (!a.is_array() || a.empty()) {
      problems.add_once("/grids/delta_star", "must be a non-empty array of positive numbers");
      return;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!is_number(a[i]) || !(a[i].get<double>() > 0) || !std::isfinite(a[i].get<double>())) {
        problems.add_once("/grids/delta_star/" + std::to_string(i), "cell size Δ* must be a positive number");
        continue;
      }
      s.grid_delta_star.push_back(a[i].get<double>());
    }
    return;
  }
  const json& a = (*g)["cells"];
  if (!a.is_array() || a.empty()) {
    problems.add_once("/grids/cells", "must be a non-empty array of [nx, ny, nz]");
    return;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string at = "/grids/cells/" + std::to_string(i);
    if (!a[i].is_array() || a[i].size() != 3) {
      problems.add_once(at, "must be [nx, ny, nz]");
      continue;
    }
    std::array<int, 3> c{};
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      const json& v = a[i][k];
      if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000) {
        problems.add_once(at + "/" + std::to_string(k), "cells must be an integer ≥ 1");
        ok = false;
        continue;
      }
      c[k] = v.get<int>();
    }
    if (ok) s.grid_cells.push_back(c);
  }
}

void parse_extrapolation(const json& doc, Study& s, ProblemList& problems) {
  auto e = doc.find("extrapolation");
  if (e == doc.end()) return;
  if (!e->is_object()) {
    problems.add_once("/extrapolation", "must be an object");
    return;
  }
  if (auto w = e->find("weights"); w != e->end()) {
    if (!w->is_string() || (*w != "inverse_h" && *w != "uniform"))
      problems.add_once("/extrapolation/weights", "must be \"inverse_h\" or \"uniform\"");
    else
      s.extrapolation.weights = w->get<std::string>();
  }
  if (auto m = e->find("method"); m != e->end()) {
    if (!m->is_string() || (*m != "averaged" && *m != "capped" && *m != "fm" && *m != "eh14"))
      problems.add_once("/extrapolation/method", "must be \"averaged\", \"capped\", \"fm\" or \"eh14\"");
    else
      s.extrapolation.method = m->get<std::string>();
  }
  if (auto p = e->find("p_range"); p != e->end()) {
    if (!p->is_array() || p->size() != 2 || !is_number((*p)[0]) || !is_number((*p)[1]) ||
        !((*p)[0].get<double>() < (*p)[1].get<double>()))
      problems.add_once("/extrapolation/p_range", "must be [low, high] with low < high");
    else {
      s.extrapolation.p_low = (*p)[0].get<double>();
      s.extrapolation.p_high = (*p)[1].get<double>();
    }
  }
  if (auto o = e->find("expected_order"); o != e->end()) {
    if (!is_number(*o) || !(o->get<double>() > 0))
      problems.add_once("/extrapolation/expected_order", "must be a number > 0 (the formal order of the scheme)");
    else
      s.extrapolation.expected_order = o->get<double>();
  }
}

// A particle file is read at validation, as the worker reads it: a particle
// outside the domain, overlapping another or of no size is refused now,
// not as a failed job later (docs/PARTICLES.md).
void check_particle_file(const CaseSpec& spec, const std::string& at, ProblemList& problems) {
  if (!std::holds_alternative<FileSpec>(spec.particles)) return;
  try {
    load_particles(spec.particles, spec);
  } catch (const InputError& e) {
    const auto& all = e.problems();
    if (all.empty()) return;
    std::string reason = "the file does not fit the case: " + all.front().where + ": " + all.front().reason;
    if (all.size() > 1) reason += " (and " + std::to_string(all.size() - 1) + " more)";
    problems.add(child_pointer(at, "particles") + "/file", reason);
  }
}

void parse_cases(const json& doc, const std::filesystem::path& base_dir, Study& s, ProblemList& problems) {
  auto cs = doc.find("cases");
  if (cs == doc.end() || !cs->is_object() || cs->empty()) {
    problems.add_once("/cases", "at least one case is required");
    return;
  }
  for (auto it = cs->begin(); it != cs->end(); ++it) {
    const std::string at = child_pointer("/cases", it.key());
    if (!it->is_object()) {
      problems.add_once(at, "a case must be an object");
      continue;
    }
    StudyCase c;
    c.name = it.key();
    c.doc = *it;
    if (!c.doc.contains("name")) c.doc["name"] = c.name;
    if (c.doc.contains("external")) {  // read after the grids (parse_external_cases)
      s.cases.push_back(std::move(c));
      continue;
    }
    ProblemList case_problems;
    try {
      c.spec = parse_case(c.doc, at, base_dir, case_problems);
    } catch (const InputError& e) {
      case_problems.append(e.problems());
    }
    check_case_physics(c.doc, at, base_dir, case_problems);
    if (case_problems.empty()) check_particle_file(c.spec, at, case_problems);
    for (const auto& p : case_problems.problems()) problems.add_once(p.where, p.reason);
    // The job is run from another folder: particle files become absolute.
    if (c.doc.contains("particles") && c.doc["particles"].is_object() &&
        c.doc["particles"].contains("file") && c.doc["particles"]["file"].is_string()) {
      std::filesystem::path f = c.doc["particles"]["file"].get<std::string>();
      if (f.is_relative()) c.doc["particles"]["file"] = std::filesystem::absolute(base_dir / f).lexically_normal().string();
    }
    s.cases.push_back(std::move(c));
  }
}

// External cases (study/external_case.h): all cases of the study or none,
// grids given as variables, none of the physical study's sections.
void parse_external_cases(const json& doc, const std::filesystem::path& base_dir, Study& s, ProblemList& problems,
                          bool cases_sound) {
  std::size_t external = 0;
  for (const auto& c : s.cases) external += c.doc.contains("external") ? 1 : 0;
  const bool variables = doc.contains("grids") && doc["grids"].is_object() && doc["grids"].contains("variables");
  if (external == 0) {
    if (variables)
      problems.add_once("/grids/variables", "grid variables are for external cases; this study's cases are physical");
    return;
  }
  if (external != s.cases.size()) {
    problems.add_once("/cases", "a study's cases are either all external or all physical; put the external ones "
                                "in a study of their own");
    return;
  }
  if (!variables)
    problems.add_once("/grids", "external cases take their grids as {\"variables\": {\"N\": [...]}}, or as an adaptive "
                                "ladder {\"target_rde\": ..., \"ratio\": ..., \"variables\": {\"N\": {\"coarsest\": ..., "
                                "\"finest\": ...}}}");
  for (const char* key : {"alignment", "numerics"})
    if (doc.contains(key))
      problems.add_once(std::string("/") + key, "does not apply to external cases (their settings are the template's)");
  if (s.adaptive_grids && s.adaptive_grids->variable) {  // a ladder in h per case (study/external_ladder.h)
    if (!cases_sound) return;
    const AdaptiveVariable& v = *s.adaptive_grids->variable;
    const GridVariables ends = {{v.name, {v.coarsest, v.finest}}};  // the expressions checked at both ends
    for (auto& c : s.cases) {
      const std::string at = child_pointer("/cases", c.name) + "/external";
      c.external = parse_external_case(c.doc["external"], at, base_dir, ends, problems, external_factor_names(s));
      if (!c.external) continue;
      ExternalLadder ladder = external_ladder(*c.external, v, s.adaptive_grids->ratio, c.name, problems);
      if (!ladder.h_nominal.empty()) s.external_ladders[c.name] = std::move(ladder);
    }
    return;
  }
  if (!cases_sound || (variables && s.grid_variables.empty())) return;  // their problems are reported
  if (external_grid_count(s.grid_variables) < 1) return;
  for (auto& c : s.cases) {
    const std::string at = child_pointer("/cases", c.name) + "/external";
    c.external = parse_external_case(c.doc["external"], at, base_dir, s.grid_variables, problems,
                                     external_factor_names(s));
  }
}

// Grids that are equal for a case, memory above the machine's.
void check_grids(const Study& s, ProblemList& problems) {
  const double machine = static_cast<double>(physical_memory_bytes());
  // A grid list's problems are at the grid; an adaptive ladder's at the
  // field that makes its rungs, naming the rung (the file lists none).
  const auto where = [&](std::size_t i, const char* ladder_field) {
    return s.adaptive_grids ? std::string("/grids/") + ladder_field : grid_pointer(s, i);
  };
  const auto what = [&](std::size_t i) {
    return s.adaptive_grids ? "ladder rung " + std::to_string(i + 1) + " (Δ* " + format_number("%.4g", s.grid_delta_star[i]) + ") "
                            : std::string();
  };
  for (const auto& c : s.cases) {
    const auto grids = grids_for_case(s, c);
    std::vector<bool> refused(grids.size(), false);  // a refused grid is no neighbour to compare with
    for (std::size_t i = 0; i < grids.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j)
        if (grids[i] == grids[j] && !refused[j])
          problems.add_once(where(i, "ratio"), what(i) + "gives the same cells as " +
                                                   (s.adaptive_grids ? "ladder rung " + std::to_string(j + 1)
                                                                     : grid_pointer(s, j)) +
                                                   " for case " + c.name);
      if (std::any_of(grids[i].begin(), grids[i].end(), [](int n) { return n > kMaxCellsPerAxis; })) {
        problems.add_once(where(i, "finest_delta_star"),
                 what(i) + "gives more than " + std::to_string(kMaxCellsPerAxis) + " cells along one direction for case " +
                     c.name + " (docs/LIMITS.md)");
        refused[i] = true;
        continue;
      }
      if (grids[i][1] < kMinFlowCells) {
        problems.add_once(where(i, "coarsest_delta_star"),
                          what(i) + "gives " + std::to_string(grids[i][1]) + " cell along y, the flow direction, for case " +
                              c.name + "; at least " + std::to_string(kMinFlowCells) +
                              " are needed (docs/LIMITS.md)");
        refused[i] = true;
        continue;
      }
      const double mem = estimated_memory_bytes(grids[i]);
      if (machine > 0 && mem > machine && !s.adaptive_grids)  // adaptive: a cap, not an error
        problems.add_once(where(i, ""),
                 "estimated memory " + human_bytes(mem) + " exceeds this machine's " + human_bytes(machine));
    }
  }
}

// Filter widths wider than a case's whole domain (the worker refuses the
// job too; here the pointer names the study's level).
void check_filter_widths(const json& doc, const Study& s, ProblemList& problems) {
  const auto f = doc.find("factors");
  if (f == doc.end() || !f->is_object() || !f->contains("fwhm_dp")) return;
  for (std::size_t i = 0; i < s.factors.fwhm_dp.size(); ++i)
    for (const auto& c : s.cases) {
      const auto& l = c.spec.domain_dp;
      const double largest = std::max({l[0], l[1], l[2]});
      if (largest > 0 && s.factors.fwhm_dp[i] > largest) {
        problems.add_once("/factors/fwhm_dp/" + std::to_string(i),
                          "the filter width " + json(s.factors.fwhm_dp[i]).dump() +
                              " d_p exceeds the largest extent " + json(largest).dump() + " d_p of case " +
                              c.name + "'s domain (docs/LIMITS.md)");
        break;
      }
    }
}

// parse_job on one job per series catches numerics problems (tolerances,
// iterations, ...) with the job's own rules; pointers map back to the study.
void check_jobs(const Study& s, ProblemList& problems) {
  for (const auto& key : design_series(s)) {
    const StudyCase* c = s.find_case(key.case_name);
    if (c == nullptr) continue;
    const auto grids = grids_for_case(s, *c);
    if (grids.empty()) continue;
    try {
      parse_job(make_job_document(s, key, grids.front()), s.base_dir);
    } catch (const InputError& e) {
      for (const auto& p : e.problems()) {
        std::string where = p.where;
        if (where.rfind("/case", 0) == 0) where = child_pointer("/cases", c->name) + where.substr(5);
        problems.add_once(where, p.reason + " (series " + key.label() + ")");
      }
    }
  }
}

// Refuses an over-long name or description at once, before the schema's
// pattern or any later step reads a 50 MB string (docs/LIMITS.md).
void check_text_lengths(const json& doc) {
  ProblemList problems;
  auto check = [&](const char* key, std::size_t limit, const std::string& why) {
    const auto it = doc.find(key);
    if (it == doc.end() || !it->is_string()) return;
    const std::size_t size = it->get_ref<const std::string&>().size();
    if (size > limit)
      problems.add(std::string("/") + key, "is " + std::to_string(size) + " characters long; at most " +
                                               std::to_string(limit) + " are allowed" + why);
  };
  check("name", kMaxStudyNameLength, " (it names the report folder)");
  check("description", kMaxStudyDescriptionLength, "");
  problems.throw_if_any();
}

// An empty {"one_at_a_time": {}} names no baseline: most likely forgotten.
void check_baseline_given(const json& doc, ProblemList& problems) {
  const auto d = doc.find("design");
  if (d == doc.end() || !d->is_object()) return;
  const auto b = d->find("one_at_a_time");
  if (b != d->end() && b->is_object() && b->empty())
    problems.add_once("/design/one_at_a_time",
                      "names no baseline; give at least one of case, convection, fwhm_dp, drag, deposition (the "
                      "fields left out are the first case and the first level of each factor)");
}

// The slurm block's keys and types are the schema's; its extra sbatch words
// are checked here with the Slurm executor's own rule (study/slurm_block.h),
// so that validate refuses what `run --executor slurm` would.
void check_slurm_block(const json& doc, ProblemList& problems) {
  const auto s = doc.find("slurm");
  if (s == doc.end() || !s->is_object()) return;
  const auto args = s->find("sbatch_args");
  if (args == s->end() || !args->is_array()) return;
  for (std::size_t i = 0; i < args->size(); ++i) {
    if (!(*args)[i].is_string()) continue;
    const std::string word = (*args)[i].get<std::string>();
    if (const auto option = sbatch_option_set_by_gridfree(word); !option.empty())
      problems.add_once("/slurm/sbatch_args/" + std::to_string(i),
                        "'" + word.substr(0, 64) + "' passes " + option + ", which gridfree sets itself");
  }
}

// Whether a problem is at or inside one of `roots` (JSON pointers), or at
// the document itself.
bool problems_under(const ProblemList& problems, std::initializer_list<const char*> roots) {
  for (const auto& p : problems.problems()) {
    if (p.where.empty() || p.where == "/") return true;
    for (const std::string root : roots)
      if (p.where == root || p.where.rfind(root + "/", 0) == 0 || p.where.rfind(root + " ", 0) == 0) return true;
  }
  return false;
}

}  // namespace

Study parse_study_document(const json& given, const std::filesystem::path& base_dir) {
  ProblemList problems;
  if (!given.is_object()) throw InputError("", "a study must be a JSON object");
  check_text_lengths(given);
  // Cases that extend others are resolved first; the rest reads the result.
  const json doc = resolve_case_extends(given, problems);
  problems.append(validate_against_schema(doc, "study.schema"));

  Study s;
  s.definition = given;
  s.base_dir = base_dir;
  if (auto n = doc.find("name"); n == doc.end() || !n->is_string() || n->get<std::string>().empty()) {
    problems.add_once("/name", "a non-empty study name is required");
  } else {
    s.name = n->get<std::string>();
    const bool safe = std::all_of(s.name.begin(), s.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.';
    });
    if (!safe || s.name.front() == '.')
      problems.add_once("/name", "use letters, digits, '-', '_' and '.' only (it names the report folder)");
  }
  if (auto n = doc.find("numerics"); n != doc.end()) {
    if (n->is_object())
      s.numerics = *n;
    else
      problems.add_once("/numerics", "must be an object");
  }
  parse_cases(doc, base_dir, s, problems);
  const bool external_study =
      std::any_of(s.cases.begin(), s.cases.end(), [](const StudyCase& c) { return c.doc.contains("external"); });
  if (external_study) {  // the study's own factors (study/external_factors.h)
    parse_external_factors(doc, s, problems);
    parse_external_design(doc, s, problems);
  } else {
    parse_factors(doc, s, problems);
    default_factors(s);
    parse_design(doc, s, problems);
    check_baseline_given(doc, problems);
  }
  check_slurm_block(doc, problems);
  check_deposition_levels(s, problems);
  parse_grids(doc, s, problems);
  parse_external_cases(doc, base_dir, s, problems, !problems_under(problems, {"/cases", "/grids"}));
  parse_alignment(doc, s, problems);  // study_alignment.cpp
  parse_extrapolation(doc, s, problems);
  parse_ensembles(doc, s, problems);
  if (!problems_under(problems, {"/cases", "/grids", "/cores"})) check_study_cores(doc, s, problems);
  // The checks of whole grids and jobs need sound parts; each runs when the
  // parts it reads are, so independent problems are reported together.
  if (external_study) {
    if (!problems_under(problems, {"/cases", "/grids", "/factors"})) check_external_factor_placeholders(s, problems);
    if (!problems.empty()) throw InputError(without_follow_ons(problems.problems()));
    return s;  // external cases: the checks below read physical cases
  }
  if (!problems_under(problems, {"/cases", "/factors"})) check_filter_widths(doc, s, problems);
  if (!problems_under(problems, {"/cases", "/grids"})) check_grids(s, problems);
  if (!problems_under(problems, {"/cases", "/grids", "/factors", "/design", "/numerics", "/ensembles"})) check_jobs(s, problems);
  // Each problem once; none inside a value that could not be read (a string
  // domain_dp has no elements to be > 0): core/follow_on_problems.h.
  if (!problems.empty()) throw InputError(without_follow_ons(problems.problems()));
  return s;
}

Study parse_study(const std::filesystem::path& file) {
  const json doc = read_json_file(file);
  auto dir = std::filesystem::absolute(file).parent_path();
  return parse_study_document(doc, dir);
}

}  // namespace gridfree
