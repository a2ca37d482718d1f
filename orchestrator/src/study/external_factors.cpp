// SPDX-License-Identifier: GPL-3.0-or-later
// Factors and design of an external study (study/external_factors.h).
#include "study/external_factors.h"

#include <algorithm>
#include <cctype>

#include "core/json_fields.h"
#include "study/design_baseline.h"
#include "study/study.h"

namespace gridfree {
namespace {

using nlohmann::json;

bool valid_factor_name(const std::string& n) {
  if (n.empty() || !(std::isalpha(static_cast<unsigned char>(n.front())) || n.front() == '_')) return false;
  return std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

bool is_level(const json& v) { return v.is_string() || (v.is_number() && !v.is_boolean()); }

}  // namespace

std::string level_text(const json& level) { return level.is_string() ? level.get<std::string>() : level.dump(); }

void parse_external_factors(const json& doc, Study& s, ProblemList& problems) {
  const auto f = doc.find("factors");
  if (f == doc.end()) return;
  if (!f->is_object()) {
    problems.add_once("/factors", "must be an object: factor name (a placeholder @@name@@ of the template) -> [levels]");
    return;
  }
  for (auto it = f->begin(); it != f->end(); ++it) {
    const std::string at = child_pointer("/factors", it.key());
    if (!valid_factor_name(it.key())) {
      problems.add_once(at, "a factor of an external study is a placeholder name: a letter or '_' followed by "
                            "letters, digits or '_'");
      continue;
    }
    if (it.key() == kExternalCoresPlaceholder) {
      problems.add_once(at, "'cores' is the job's number of cores (@@cores@@, the study's cores rule), not a factor");
      continue;
    }
    if (!it->is_array() || it->empty()) {
      problems.add_once(at, "must be an array of at least one level (strings or numbers)");
      continue;
    }
    std::vector<std::string> levels;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& v = (*it)[i];
      const std::string where = at + "/" + std::to_string(i);
      if (!is_level(v)) {
        problems.add_once(where, "a level is a string or a number (substituted as text for @@" + it.key() + "@@)");
        continue;
      }
      const std::string text = level_text(v);
      if (std::find(levels.begin(), levels.end(), text) != levels.end()) {
        problems.add_once(where, "level '" + text + "' is listed twice");
        continue;
      }
      levels.push_back(text);
    }
    s.factors.external[it.key()] = std::move(levels);
  }
}

void parse_external_design(const json& doc, Study& s, ProblemList& problems) {
  const json* baseline = one_at_a_time_baseline(doc, problems);
  if (baseline == nullptr) return;
  const json& b = *baseline;
  const std::string at = "/design/one_at_a_time";
  SeriesKey key;
  key.case_name = s.cases.empty() ? "" : s.cases.front().name;
  for (const auto& [name, levels] : s.factors.external)
    if (!levels.empty()) key.levels[name] = levels.front();
  std::string valid = "case";
  for (const auto& [name, levels] : s.factors.external) valid += ", " + name;
  if (b.empty())
    problems.add_once(at, "names no baseline; give at least one of " + valid +
                              " (the fields left out are the first case and the first level of each factor)");
  for (auto it = b.begin(); it != b.end(); ++it) {
    const std::string where = child_pointer(at, it.key());
    if (it.key() == "case") {
      if (!it->is_string()) {
        problems.add_once(where, "must be a case name (string)");
      } else if (s.find_case(it->get<std::string>()) == nullptr) {
        problems.add_once(where, "unknown case '" + it->get<std::string>() + "' (not in /cases)");
      } else {
        key.case_name = it->get<std::string>();
      }
      continue;
    }
    const auto factor = s.factors.external.find(it.key());
    if (factor == s.factors.external.end()) {
      problems.add_once(where, "unknown baseline field; valid: " + valid);
      continue;
    }
    if (!is_level(*it)) {
      problems.add_once(where, "must be a level of /factors/" + it.key() + " (a string or a number)");
      continue;
    }
    const std::string text = level_text(*it);
    if (std::find(factor->second.begin(), factor->second.end(), text) == factor->second.end()) {
      problems.add_once(where, "baseline " + it.key() + " '" + text + "' is not a level of /factors/" + it.key());
      continue;
    }
    key.levels[it.key()] = text;
  }
  s.baseline = key;
}

std::set<std::string> external_factor_names(const Study& s) {
  std::set<std::string> out;
  for (const auto& [name, levels] : s.factors.external) out.insert(name);
  return out;
}

void check_external_factor_placeholders(const Study& s, ProblemList& problems) {
  for (const auto& [name, levels] : s.factors.external) {
    const std::string at = child_pointer("/factors", name);
    if (s.grid_variables.count(name) != 0 ||
        (s.adaptive_grids && s.adaptive_grids->variable && s.adaptive_grids->variable->name == name)) {
      problems.add_once(at, "'" + name + "' is a grid variable (/grids/variables); a factor is a placeholder of its own");
      continue;
    }
    for (const auto& c : s.cases) {
      if (!c.external) continue;
      if (c.external->constants.count(name) != 0) {
        problems.add_once(at, "'" + name + "' is a constant of case " + c.name +
                                  " (external/constants); a factor is a placeholder of its own");
        break;
      }
      if (c.external->variables.count(name) != 0) {
        problems.add_once(at, "'" + name + "' is a derived variable of case " + c.name +
                                  " (external/variables); a factor is a placeholder of its own");
        break;
      }
      const auto used = rendered_placeholders(*c.external);
      if (used.count(name) == 0) {
        std::string files;
        for (const auto& r : c.external->render) files += (files.empty() ? "" : ", ") + r;
        problems.add_once(at, "no rendered file of case " + c.name + " (" + (files.empty() ? "none" : files) +
                                  ") has the placeholder @@" + name + "@@, so its levels would change nothing");
        break;
      }
    }
  }
}

}  // namespace gridfree
