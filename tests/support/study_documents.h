// SPDX-License-Identifier: GPL-3.0-or-later
// Study documents parsed as files of studies/ for the study tests: the
// study, or the problems it is refused with.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "project_paths.h"
#include "study/study.h"

namespace gridfree::test_support {

// `doc` parsed as if it were a file in studies/ (the folder its relative
// paths are resolved against).
inline Study study_of(const nlohmann::json& doc) { return parse_study_document(doc, kSourceDir / "studies"); }

// The problems `doc` is refused with (none when it parses).
inline std::vector<Problem> study_problems(const nlohmann::json& doc) {
  try {
    study_of(doc);
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

// Their JSON pointers.
inline std::vector<std::string> problem_paths(const nlohmann::json& doc) {
  std::vector<std::string> out;
  for (const auto& p : study_problems(doc)) out.push_back(p.where);
  return out;
}

// The message `doc` is refused with, "(accepted)" when it parses.
inline std::string refusal(const nlohmann::json& doc) {
  try {
    study_of(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// Whether `paths` holds `path`.
inline bool contains(const std::vector<std::string>& paths, const std::string& path) {
  return std::find(paths.begin(), paths.end(), path) != paths.end();
}

}  // namespace gridfree::test_support
