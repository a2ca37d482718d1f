// SPDX-License-Identifier: GPL-3.0-or-later
// resolve_case_extends (study/case_extends.h): depth-first over the chain of
// bases, with the chain kept to report cycles.
#include "study/case_extends.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "core/json_fields.h"

namespace gridfree {
namespace {

using nlohmann::json;

class Resolver {
 public:
  Resolver(const json& cases, ProblemList& problems) : cases_(cases), problems_(problems) {}

  // The resolved case, or null when its chain is broken.
  json resolve(const std::string& name) {
    if (auto it = done_.find(name); it != done_.end()) return it->second;
    if (std::find(chain_.begin(), chain_.end(), name) != chain_.end()) {
      std::string cycle;
      for (const auto& n : chain_) cycle += n + " -> ";
      problems_.add(child_pointer("/cases", chain_.back()) + "/extends", "cycle: " + cycle + name);
      return nullptr;
    }
    const json& c = cases_.at(name);
    json own = c;
    own.erase("extends");
    if (!c.contains("extends")) return done_[name] = own;

    const std::string at = child_pointer("/cases", name) + "/extends";
    const json& base = c["extends"];
    json out = nullptr;
    if (!base.is_string()) {
      problems_.add(at, "must be the name of another case of this study");
    } else if (!cases_.contains(base.get<std::string>()) || !cases_[base.get<std::string>()].is_object()) {
      problems_.add(at, "unknown case '" + base.get<std::string>() + "' (not in /cases)");
    } else {
      chain_.push_back(name);
      json resolved_base = resolve(base.get<std::string>());
      chain_.pop_back();
      const auto& ps = problems_.problems();
      const bool reported = std::any_of(ps.begin(), ps.end(), [&](const Problem& p) { return p.where == at; });
      if (resolved_base.is_null()) {
        if (!reported) problems_.add(at, "its base case '" + base.get<std::string>() + "' cannot be resolved (see there)");
      } else {
        resolved_base.merge_patch(own);
        if (!own.contains("name")) resolved_base.erase("name");  // a case's name is its own
        out = resolved_base;
      }
    }
    done_[name] = out;
    return out;
  }

 private:
  const json& cases_;
  ProblemList& problems_;
  std::vector<std::string> chain_;
  std::map<std::string, json> done_;
};

}  // namespace

json resolve_case_extends(const json& study_doc, ProblemList& problems) {
  if (!study_doc.is_object()) return study_doc;
  auto cs = study_doc.find("cases");
  if (cs == study_doc.end() || !cs->is_object()) return study_doc;
  json out = study_doc;
  Resolver r(*cs, problems);
  for (auto it = cs->begin(); it != cs->end(); ++it) {
    if (!it->is_object() || !it->contains("extends")) continue;
    json resolved = r.resolve(it.key());
    if (resolved.is_null())
      out["cases"].erase(it.key());  // its problem is reported; the rest would be noise
    else
      out["cases"][it.key()] = resolved;
  }
  return out;
}

json resolved_case(const json& study_doc, const std::string& name) {
  if (!study_doc.is_object()) return nullptr;
  auto cs = study_doc.find("cases");
  if (cs == study_doc.end() || !cs->is_object() || !cs->contains(name) || !(*cs)[name].is_object()) return nullptr;
  ProblemList ignored;  // a broken chain gives null
  return Resolver(*cs, ignored).resolve(name);
}

}  // namespace gridfree
