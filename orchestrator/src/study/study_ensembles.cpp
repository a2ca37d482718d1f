// SPDX-License-Identifier: GPL-3.0-or-later
// parse_ensembles: the "ensembles" field of a study (see study_ensembles.h).
#include "study/study_ensembles.h"

#include <algorithm>
#include <cctype>

#include "study/study.h"

namespace gridfree {
namespace {

using nlohmann::json;

bool safe_ensemble_name(const std::string& n) {
  if (n.empty() || n.front() == '.' || n.front() == '-' || n.front() == '_') return false;
  return std::all_of(n.begin(), n.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.';
  });
}


}  // namespace

void parse_ensembles(const json& doc, Study& s, ProblemList& problems) {
  auto e = doc.find("ensembles");
  if (e == doc.end()) return;
  if (!e->is_object()) {
    problems.add_once("/ensembles", "must be an object: ensemble name -> [case names]");
    return;
  }
  std::map<std::string, std::string> owner;  // case → the ensemble that listed it first
  for (auto it = e->begin(); it != e->end(); ++it) {
    const std::string& name = it.key();
    // A safe name needs no JSON-pointer escaping (~ and / are refused).
    const std::string at = "/ensembles/" + name;
    if (!safe_ensemble_name(name)) {
      std::string token;
      for (char ch : name) token += ch == '~' ? std::string("~0") : ch == '/' ? std::string("~1") : std::string(1, ch);
      problems.add_once("/ensembles/" + token,
               "ensemble name '" + name + "': use letters, digits, '-', '_' and '.' (it names report files)");
      continue;
    }
    if (!it->is_array()) {
      problems.add_once(at, "must be an array of case names");
      continue;
    }
    if (it->size() < 2)
      problems.add_once(at, "an ensemble needs at least two instances (cases); it has " +
                                 std::to_string(it->size()));
    std::vector<std::string> cases;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string where = at + "/" + std::to_string(i);
      const json& v = (*it)[i];
      if (!v.is_string()) {
        problems.add_once(where, "must be a case name (string)");
        continue;
      }
      const std::string c = v.get<std::string>();
      if (s.find_case(c) == nullptr) {
        problems.add_once(where, "unknown case '" + c + "' (not in /cases)");
        continue;
      }
      if (std::find(cases.begin(), cases.end(), c) != cases.end()) {
        problems.add_once(where, "case '" + c + "' is listed twice in this ensemble");
        continue;
      }
      if (auto o = owner.find(c); o != owner.end()) {
        problems.add_once(where, "case '" + c + "' is already in ensemble '" + o->second +
                                      "'; a case is an instance of one physical state only");
        continue;
      }
      // Instances of one state share the domain, so grid i is the same Δ* in each.
      if (!cases.empty() && s.find_case(c)->spec.domain_dp != s.find_case(cases.front())->spec.domain_dp) {
        problems.add_once(where, "case '" + c + "' has another domain_dp than '" + cases.front() +
                                      "'; the instances of an ensemble share the domain");
        continue;
      }
      owner[c] = name;
      cases.push_back(c);
    }
    s.ensembles[name] = cases;
  }
}

std::string ensemble_of(const Ensembles& ensembles, const std::string& case_name) {
  for (const auto& [name, cases] : ensembles)
    if (std::find(cases.begin(), cases.end(), case_name) != cases.end()) return name;
  return "";
}

}  // namespace gridfree
