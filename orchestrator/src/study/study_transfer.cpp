// SPDX-License-Identifier: GPL-3.0-or-later
// Transfer methods as a study factor (study_transfer.h).
#include "study/study_transfer.h"

#include <algorithm>
#include <array>

#include "deposition/filter_integration.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

// The level names that are not transfer objects (docs/TRANSFER.md presets and kinds).
constexpr std::array<const char*, 4> kNamedLevels{"diffusion", "centroid", "fm18", "mfix"};
// Fields of an object level, in the order an automatic name lists them, with their short form.
constexpr std::array<std::pair<const char*, const char*>, 7> kLevelFields{{{"preset", "preset"},
                                                                          {"pre_deposition", "pre"},
                                                                          {"sampling", "samp"},
                                                                          {"integration", "int"},
                                                                          {"steps", "steps"},
                                                                          {"diffusivity", "diff"},
                                                                          {"truncation_sigmas", "trunc"}}};

bool is_named_level(const std::string& n) {
  return std::any_of(kNamedLevels.begin(), kNamedLevels.end(), [&](const char* k) { return n == k; });
}

bool safe_level_name(const std::string& n) {
  return !n.empty() && n.size() <= 40 && std::all_of(n.begin(), n.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == '+' ||
           c == '=' || c == ',';
  });
}

// "pre=trilinear,samp=cell": the given fields, short and in a fixed order.
std::string automatic_name(const json& level) {
  std::string out;
  for (const auto& [key, brief] : kLevelFields) {
    auto it = level.find(key);
    if (it == level.end()) continue;
    if (!out.empty()) out += ",";
    out += std::string(brief) + "=" + (it->is_string() ? it->get<std::string>() : it->dump());
  }
  return out;
}

// The level's pointer in the file (levels refused before it do not shift it).
std::string level_pointer(const Study& s, const std::string& name) {
  if (const auto at = s.deposition_level_index.find(name); at != s.deposition_level_index.end())
    return "/factors/deposition/" + std::to_string(at->second);
  const auto& levels = s.factors.deposition;
  const auto i = std::find(levels.begin(), levels.end(), name) - levels.begin();
  return "/factors/deposition/" + std::to_string(i);
}

}  // namespace

void parse_deposition_levels(const json& f, const std::string& at, Study& s, ProblemList& problems) {
  if (!f.is_array()) {
    problems.add(at, "must be an array of names or transfer objects");
    return;
  }
  if (f.empty()) problems.add(at, "a factor needs at least one level");
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::string where = at + "/" + std::to_string(i);
    std::string name;
    if (f[i].is_string()) {
      name = f[i].get<std::string>();
      if (!is_named_level(name)) {
        problems.add(where, "unknown '" + name + "'; valid: diffusion, centroid, fm18, mfix, or a transfer object");
        continue;
      }
    } else if (f[i].is_object()) {
      json level = f[i];
      if (auto n = level.find("name"); n != level.end()) {
        name = n->is_string() ? n->get<std::string>() : "";
        level.erase("name");
        if (!safe_level_name(name)) {
          problems.add(where + "/name", "use up to 40 letters, digits and - _ . + = , (it names the series)");
          continue;
        }
        if (is_named_level(name)) {
          problems.add(where + "/name", "'" + name + "' is a built-in level; give the object another name");
          continue;
        }
      } else {
        name = automatic_name(level);
      }
      if (level.empty()) {
        problems.add(where, "a transfer object needs at least one of preset, pre_deposition, sampling, "
                            "diffusivity, integration, steps, truncation_sigmas");
        continue;
      }
      s.transfer_levels[name] = level;
    } else {
      problems.add(where, "must be a level name or a transfer object");
      continue;
    }
    if (std::find(s.factors.deposition.begin(), s.factors.deposition.end(), name) != s.factors.deposition.end()) {
      problems.add(where, "level '" + name + "' is listed twice");
      continue;
    }
    s.factors.deposition.push_back(name);
    s.deposition_level_index[name] = i;
  }
}

json deposition_document(const Study& s, const std::string& level, double fwhm_dp) {
  json dep = s.numerics.is_object() && s.numerics.contains("deposition") && s.numerics["deposition"].is_object()
                 ? s.numerics["deposition"] : json::object();
  if (auto t = s.transfer_levels.find(level); t != s.transfer_levels.end()) {
    if (t->second.contains("preset")) {
      dep = t->second;  // a preset fixes every transfer field
    } else {
      dep["kind"] = "diffusion";
      for (auto it = t->second.begin(); it != t->second.end(); ++it) dep[it.key()] = it.value();
      // A level that chooses an integration without steps drops the study's
      // step count (the worker refuses steps with any other integration).
      if (t->second.contains("integration") && t->second["integration"] != "steps" && !t->second.contains("steps"))
        dep.erase("steps");
    }
  } else if (level == "fm18" || level == "mfix") {
    dep = {{"preset", level}};  // a preset fixes every transfer field (docs/TRANSFER.md)
  } else if (level == "centroid") {
    dep = {{"kind", "centroid"}};  // no filter, cell values: the transfer fields do not apply
  } else {
    dep["kind"] = level;
  }
  dep["fwhm_dp"] = fwhm_dp;
  return dep;
}

TransferColumns transfer_columns(const json& deposition) {
  ProblemList problems;
  const DepositionSpec d = parse_deposition(deposition, "/numerics/deposition", problems);
  problems.throw_if_any();
  TransferColumns c;
  c.pre_deposition = std::string(pre_deposition_name(d.pre_deposition));
  c.sampling = std::string(sampling_name(d.sampling));
  const bool filtered = d.kind == DepositionKind::kDiffusion && d.pre_deposition != PreDeposition::kGaussian;
  if (filtered) {
    c.integration = std::string(filter_integration_name(d.integration));
    c.diffusivity = std::string(filter_diffusivity_name(d.diffusivity));
    if (d.integration == FilterIntegration::kSteps) c.steps = d.steps;
  }
  return c;
}

void check_deposition_levels(const Study& s, ProblemList& problems) {
  const double fwhm = s.factors.fwhm_dp.empty() ? 6.0 : s.factors.fwhm_dp.front();
  const json* study_dep = s.numerics.is_object() && s.numerics.contains("deposition") &&
                                  s.numerics["deposition"].is_object()
                              ? &s.numerics["deposition"]
                              : nullptr;
  // A field of the study's numerics.deposition that contradicts the levels
  // is reported once, at that field, naming every level it breaks.
  struct StudyFieldProblem {
    std::string where, reason;
    std::vector<std::string> levels;
  };
  std::vector<StudyFieldProblem> from_study;
  std::vector<std::pair<std::string, json>> expanded;  // level → explicit transfer
  for (const auto& name : s.factors.deposition) {
    const std::string at = level_pointer(s, name);
    const json dep = deposition_document(s, name, fwhm);
    ProblemList level_problems;
    const DepositionSpec d = parse_deposition(dep, at, level_problems);
    const auto t = s.transfer_levels.find(name);
    for (const auto& p : level_problems.problems()) {
      const std::string key = p.where.size() > at.size() + 1 ? p.where.substr(at.size() + 1) : "";
      const bool level_sets = t != s.transfer_levels.end() && t->second.contains(key);
      if (!key.empty() && !level_sets && study_dep != nullptr && study_dep->contains(key)) {
        const std::string where = "/numerics/deposition/" + key;
        auto same = std::find_if(from_study.begin(), from_study.end(), [&](const StudyFieldProblem& q) {
          return q.where == where && q.reason == p.reason;
        });
        if (same == from_study.end()) from_study.push_back({where, p.reason, {at}});
        else same->levels.push_back(at);
      } else if (key.empty() || level_sets) {
        problems.add(p.where, p.reason);  // the level's own field, in the file
      } else {
        problems.add(at, key + ": " + p.reason);  // a field the level's name implies
      }
    }
    if (!level_problems.empty()) continue;
    json explicit_dep = deposition_json(d, dep);
    explicit_dep.erase("fwhm_dp");
    for (const auto& [other, other_dep] : expanded)
      if (other_dep == explicit_dep)
        problems.add(at, "gives the same transfer as " + level_pointer(s, other) + " ('" + other + "'): " +
                             explicit_dep.dump());
    expanded.emplace_back(name, explicit_dep);
  }
  for (const auto& q : from_study) {
    std::string levels;
    for (const auto& l : q.levels) levels += (levels.empty() ? "" : ", ") + l;
    problems.add(q.where, q.reason + " (with deposition level" + (q.levels.size() > 1 ? "s " : " ") + levels + ")");
  }
}

}  // namespace gridfree
