// SPDX-License-Identifier: GPL-3.0-or-later
// The adaptive grids' ladder and their parsing (study/adaptive_grids.h).
#include "study/adaptive_grids.h"

#include <cmath>
#include <cstdlib>

#include "study/grid_listing.h"

namespace gridfree {

std::vector<double> adaptive_ladder(const AdaptiveGrids& a) {
  std::vector<double> out;
  if (a.variable) return out;  // in h, per case (study/external_ladder.h)
  if (!(a.ratio > 1) || !(a.coarsest_delta_star > 0) || !(a.finest_delta_star > 0)) return out;
  for (int k = 0; k < 10000; ++k) {
    const double d = a.coarsest_delta_star / std::pow(a.ratio, k);
    if (d < a.finest_delta_star * (1 - 1e-9)) break;
    out.push_back(d);
  }
  return out;
}

std::optional<double> parse_memory_field(const nlohmann::json& v) {
  if (v.is_number() && !v.is_boolean()) {
    const double b = v.get<double>();
    return b > 0 && std::isfinite(b) ? std::optional<double>(b) : std::nullopt;
  }
  if (!v.is_string()) return std::nullopt;
  const std::string s = v.get<std::string>();
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !(x > 0) || !std::isfinite(x)) return std::nullopt;
  std::string unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
  const std::pair<const char*, double> units[] = {
      {"", 1},          {"B", 1},          {"KiB", 1024.0},  {"MiB", 1048576.0}, {"GiB", 1073741824.0},
      {"TiB", 1099511627776.0}, {"kB", 1e3}, {"KB", 1e3},     {"MB", 1e6},        {"GB", 1e9}, {"TB", 1e12}};
  for (const auto& [name, factor] : units)
    if (unit == name) return x * factor;
  return std::nullopt;
}

namespace {

std::optional<double> positive(const nlohmann::json& g, const char* key, ProblemList& problems, bool required) {
  const std::string at = std::string("/grids/") + key;
  auto it = g.find(key);
  if (it == g.end()) {
    if (required) problems.add(at, "required for adaptive grids (with target_rde)");
    return std::nullopt;
  }
  if (!it->is_number() || it->is_boolean() || !(it->get<double>() > 0) || !std::isfinite(it->get<double>())) {
    problems.add(at, "must be a positive number");
    return std::nullopt;
  }
  return it->get<double>();
}

// "variables": {"N": {"coarsest": 20, "finest": 160, "type": "integer"}}.
std::optional<AdaptiveVariable> parse_adaptive_variable(const nlohmann::json& v, ProblemList& problems) {
  const std::string at = "/grids/variables";
  if (!v.is_object() || v.empty()) {
    problems.add(at, "must name the grid variable the ladder refines: {\"N\": {\"coarsest\": 20, \"finest\": 160}}");
    return std::nullopt;
  }
  if (v.size() > 1) {
    std::string names;
    for (auto it = v.begin(); it != v.end(); ++it) names += (names.empty() ? "" : ", ") + it.key();
    problems.add(at, "an adaptive series refines one grid variable and maps each wanted h to it; the study gives " +
                         std::to_string(v.size()) + " (" + names +
                         "): keep one and derive the others from it in /cases/NAME/external/variables "
                         "(e.g. \"M\": \"2 * N\")");
    return std::nullopt;
  }
  AdaptiveVariable out;
  out.name = v.begin().key();
  const nlohmann::json& d = v.begin().value();
  const std::string here = at + "/" + out.name;
  if (!d.is_object()) {
    problems.add(here, "must be {\"coarsest\": value, \"finest\": value} (optionally \"type\": \"integer\" or \"real\")");
    return std::nullopt;
  }
  const std::size_t before = problems.problems().size();
  for (auto it = d.begin(); it != d.end(); ++it)
    if (it.key() != "coarsest" && it.key() != "finest" && it.key() != "type")
      problems.add(here + "/" + it.key(), "unknown field; valid: coarsest, finest, type");
  for (const char* k : {"coarsest", "finest"}) {
    auto it = d.find(k);
    if (it == d.end())
      problems.add(here + "/" + k, "required: the variable's value on the " + std::string(k) + " grid of the ladder");
    else if (!it->is_number() || it->is_boolean() || !std::isfinite(it->get<double>()))
      problems.add(here + "/" + k, "must be a finite number");
  }
  if (problems.problems().size() != before) return std::nullopt;
  out.coarsest = d["coarsest"].get<double>();
  out.finest = d["finest"].get<double>();
  out.integer = d["coarsest"].is_number_integer() && d["finest"].is_number_integer();
  if (auto t = d.find("type"); t != d.end()) {
    if (*t == "integer")
      out.integer = true;
    else if (*t == "real")
      out.integer = false;
    else
      problems.add(here + "/type", "must be \"integer\" or \"real\"");
  }
  if (out.integer && (out.coarsest != std::round(out.coarsest) || out.finest != std::round(out.finest)))
    problems.add(here, "an integer variable needs integer coarsest and finest values");
  if (out.coarsest == out.finest) problems.add(here + "/finest", "must differ from coarsest");
  if (problems.problems().size() != before) return std::nullopt;
  return out;
}

}  // namespace

std::optional<AdaptiveGrids> parse_adaptive_grids(const nlohmann::json& g, ProblemList& problems) {
  const std::size_t before = problems.problems().size();
  const bool external = g.contains("variables");  // an external study's ladder (study/external_ladder.h)
  for (auto it = g.begin(); it != g.end(); ++it) {
    const std::string& k = it.key();
    if (external && (k == "coarsest_delta_star" || k == "finest_delta_star")) {
      problems.add("/grids/" + k, "an external study's ladder is given by its grid variable (/grids/variables), "
                                  "not by Δ*");
      continue;
    }
    if (k != "target_rde" && k != "coarsest_delta_star" && k != "ratio" && k != "finest_delta_star" &&
        k != "max_cpu_s" && k != "max_memory" && k != "variables")
      problems.add("/grids/" + k,
                   k == "delta_star" || k == "cells"
                       ? "a grid list and target_rde exclude each other"
                       : "unknown field; valid with target_rde: coarsest_delta_star, ratio, finest_delta_star, "
                         "max_cpu_s, max_memory");
  }
  AdaptiveGrids a;
  const auto target = positive(g, "target_rde", problems, true);
  const auto coarsest = external ? std::optional<double>(0) : positive(g, "coarsest_delta_star", problems, true);
  const auto ratio = positive(g, "ratio", problems, true);
  const auto finest = external ? std::optional<double>(0) : positive(g, "finest_delta_star", problems, true);
  if (external) a.variable = parse_adaptive_variable(g["variables"], problems);
  a.max_cpu_s = positive(g, "max_cpu_s", problems, false);
  if (target && *target >= 1) problems.add("/grids/target_rde", "a fraction below 1 (0.01 = 1 %)");
  if (ratio && *ratio < kMinNeighbourRatio)
    problems.add("/grids/ratio", "must be at least " + std::to_string(kMinNeighbourRatio).substr(0, 3) +
                                     ": closer grids differ mostly by grid-to-grid scatter");
  if (!external && coarsest && finest && *finest >= *coarsest)
    problems.add("/grids/finest_delta_star", "must be smaller than coarsest_delta_star");
  if (auto m = g.find("max_memory"); m != g.end()) {
    a.max_memory_bytes = parse_memory_field(*m);
    if (!a.max_memory_bytes)
      problems.add("/grids/max_memory", "must be a size such as \"8 GiB\", \"500 MiB\", \"2 GB\" or a number of bytes");
  }
  if (problems.problems().size() != before) return std::nullopt;
  a.target_rde = *target;
  a.coarsest_delta_star = *coarsest;
  a.ratio = *ratio;
  a.finest_delta_star = *finest;
  if (external) return a;  // the ladder is checked per case (study/external_ladder.h)
  if (adaptive_ladder(a).size() < AdaptiveGrids::kMinLadder) {
    problems.add("/grids/finest_delta_star", "the ladder from coarsest_delta_star by ratio holds fewer than " +
                                                 std::to_string(AdaptiveGrids::kMinLadder) +
                                                 " grids down to finest_delta_star; a converged verdict needs 5");
    return std::nullopt;
  }
  return a;
}

std::optional<AdaptiveGrids> adaptive_grids_of(const nlohmann::json& definition) {
  if (!definition.is_object() || !definition.contains("grids") || !definition["grids"].is_object() ||
      !definition["grids"].contains("target_rde"))
    return std::nullopt;
  ProblemList ignored;
  return parse_adaptive_grids(definition["grids"], ignored);
}

}  // namespace gridfree
