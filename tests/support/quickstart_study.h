// SPDX-License-Identifier: GPL-3.0-or-later
// Studies made from studies/quickstart.json, the base of most test studies.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "project_paths.h"

namespace gridfree::test_support {

// studies/quickstart.json as a document.
inline nlohmann::json quickstart_document() {
  std::ifstream in(kSourceDir / "studies/quickstart.json");
  return nlohmann::json::parse(in);
}

// A study `name` of quickstart's PC1 as the one case "ok" (which the fake
// worker converges on), factorial superbee × fwhm 6 × bvk on Δ* 5, 4, 3.3;
// written to dir/<name>.json, whose path it returns.
inline std::filesystem::path write_ok_study(const std::filesystem::path& dir, const std::string& name) {
  auto doc = quickstart_document();
  doc["name"] = name;
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"ok", pc1}};
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3}}};
  const auto file = dir / (name + ".json");
  std::ofstream(file) << doc.dump(2);
  return file;
}

}  // namespace gridfree::test_support
