// SPDX-License-Identifier: GPL-3.0-or-later
// grid_listing, neighbour_warnings and their text/JSON forms (grid_listing.h).
#include "study/grid_listing.h"

#include "study/format_number.h"
#include "study/job_cores.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridfree {

std::string grid_pointer(const Study& study, std::size_t i) {
  if (study.adaptive_grids) return "/grids ladder rung " + std::to_string(i + 1);
  return (study.grid_delta_star.empty() ? "/grids/cells/" : "/grids/delta_star/") + std::to_string(i);
}

std::vector<GridRow> grid_listing(const Study& study) {
  std::vector<GridRow> rows;
  const bool requested = !study.grid_delta_star.empty();
  for (const auto& c : study.cases) {
    if (c.external) {  // external cases: h and cells from their expressions (study/external_case.h)
      const GridVariables& grids = external_grids_of(study, c.name);
      const auto ladder = study.external_ladders.find(c.name);
      for (std::size_t i = 0; i < external_grid_count(grids); ++i) {
        const ExternalGrid g = external_grid(*c.external, grids, i);
        GridRow r;
        r.case_name = c.name;
        r.index = i;
        r.pointer = ladder != study.external_ladders.end() ? grid_pointer(study, i)
                                                           : "/grids/variables level " + std::to_string(i);
        if (ladder != study.external_ladders.end()) r.requested = ladder->second.h_nominal.at(i);
        r.actual = g.h;
        r.h_meaning = c.external->h_meaning;
        r.cell_count = g.cells ? static_cast<std::uint64_t>(std::max(1.0, std::round(*g.cells))) : 0;
        r.cells = {static_cast<int>(std::min<std::uint64_t>(r.cell_count, 2000000000)), 1, 1};
        rows.push_back(r);
      }
      continue;
    }
    const auto grids = grids_for_case(study, c);
    for (std::size_t i = 0; i < grids.size(); ++i) {
      GridRow r;
      r.case_name = c.name;
      r.index = i;
      r.pointer = grid_pointer(study, i);
      if (requested) r.requested = study.grid_delta_star[i];
      r.cells = grids[i];
      r.actual = delta_star_of(c.spec.domain_dp, grids[i]);
      r.cell_count = static_cast<std::uint64_t>(grids[i][0]) * grids[i][1] * grids[i][2];
      rows.push_back(r);
    }
  }
  const std::string rule = study_cores_expression(study.definition);
  if (!rule.empty())
    for (auto& r : rows) {
      r.cores_rule = rule;
      try {
        r.cores = job_cores(rule, static_cast<double>(std::max<std::uint64_t>(1, r.cell_count)), kUncappedCores);
      } catch (const std::exception&) {
      }  // validation refused such a rule before a listing is made
    }
  return rows;
}

std::vector<std::string> neighbour_warnings(const std::vector<GridRow>& rows, double min_ratio) {
  std::vector<std::string> out;
  for (std::size_t begin = 0; begin < rows.size();) {
    std::size_t end = begin;
    while (end < rows.size() && rows[end].case_name == rows[begin].case_name) ++end;
    std::vector<const GridRow*> g;
    for (std::size_t i = begin; i < end; ++i) g.push_back(&rows[i]);
    std::sort(g.begin(), g.end(), [](const GridRow* a, const GridRow* b) { return a->actual < b->actual; });
    for (std::size_t i = 1; i < g.size(); ++i) {
      const double ratio = g[i]->actual / g[i - 1]->actual;
      const std::string h = g[i]->h_meaning.empty() ? "Δ*" : "h";  // an external case's declared h
      if (ratio < min_ratio)
        out.push_back("case " + g[i]->case_name + ": " + g[i - 1]->pointer + " (" + h + " " +
                      format_number("%.4g", g[i - 1]->actual) + ") and " + g[i]->pointer + " (" + h + " " +
                      format_number("%.4g", g[i]->actual) + ") differ by a ratio of " + format_number("%.3f", ratio) +
                      " < " + format_number("%g", min_ratio) +
                      ": their difference is mostly grid-to-grid scatter, not the trend with " + h);
    }
    begin = end;
  }
  return out;
}

namespace {

// " cores" column text of a row ("" without a rule; "-" when not a number).
std::string cores_cell(const GridRow& r) {
  if (r.cores_rule.empty()) return "";
  char cell[32];
  std::snprintf(cell, sizeof cell, " %6s", r.cores ? std::to_string(*r.cores).c_str() : "-");
  return cell;
}

std::string cores_note(const std::vector<GridRow>& rows) {
  if (rows.empty() || rows.front().cores_rule.empty()) return "";
  return "cores = " + rows.front().cores_rule +
         " per job, at most the pool's cores (the machine's, or -j when larger; under Slurm cpus_per_task)\n";
}

}  // namespace

std::string grid_listing_table(const std::vector<GridRow>& rows) {
  std::string out;
  char line[256];
  const std::string cores_head = !rows.empty() && !rows.front().cores_rule.empty() ? "  cores" : "";
  if (!rows.empty() && !rows.front().h_meaning.empty()) {  // external: h as declared, cells
    std::snprintf(line, sizeof line, "%-16s %5s %13s %12s", "case", "grid", "h", "cells");
    out += line + cores_head + "\n";
    std::vector<std::pair<std::string, std::string>> meanings;  // case → its h, in order
    for (const auto& r : rows) {
      const std::string cells = r.cell_count > 0 ? std::to_string(r.cell_count) : "-";
      std::snprintf(line, sizeof line, "%-16s %5zu %13.6g %12s", r.case_name.c_str(), r.index, r.actual, cells.c_str());
      out += line + cores_cell(r) + "\n";
      if (meanings.empty() || meanings.back().first != r.case_name) meanings.emplace_back(r.case_name, r.h_meaning);
    }
    for (const auto& [name, meaning] : meanings) out += "h of " + name + ": " + meaning + "\n";
    return out + cores_note(rows);
  }
  // "Δ" is two bytes: its columns are one wider in the header.
  std::snprintf(line, sizeof line, "%-16s %5s %13s %13s %18s %12s", "case", "grid", "Δ* requested", "Δ* actual",
                "nx x ny x nz", "cells");
  out += line + cores_head + "\n";
  for (const auto& r : rows) {
    const std::string req = r.requested ? format_number("%.4g", *r.requested) : "-";
    const std::string dims =
        std::to_string(r.cells[0]) + " x " + std::to_string(r.cells[1]) + " x " + std::to_string(r.cells[2]);
    std::snprintf(line, sizeof line, "%-16s %5zu %12s %12.4g %18s %12llu", r.case_name.c_str(), r.index, req.c_str(),
                  r.actual, dims.c_str(), static_cast<unsigned long long>(r.cell_count));
    out += line + cores_cell(r) + "\n";
  }
  return out + cores_note(rows);
}

nlohmann::json grid_listing_json(const std::vector<GridRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows) {
    if (!r.h_meaning.empty()) {  // external
      out.push_back({{"case", r.case_name},
                     {"grid", r.index},
                     {"h", r.actual},
                     {"h_meaning", r.h_meaning},
                     {"cell_count", r.cell_count > 0 ? nlohmann::json(r.cell_count) : nlohmann::json(nullptr)}});
      if (!r.cores_rule.empty()) out.back()["cores"] = r.cores ? nlohmann::json(*r.cores) : nlohmann::json(nullptr);
      continue;
    }
    out.push_back({{"case", r.case_name},
                   {"grid", r.index},
                   {"delta_star_requested", r.requested ? nlohmann::json(*r.requested) : nlohmann::json(nullptr)},
                   {"delta_star", r.actual},
                   {"cells", {r.cells[0], r.cells[1], r.cells[2]}},
                   {"cell_count", r.cell_count}});
    if (!r.cores_rule.empty()) out.back()["cores"] = r.cores ? nlohmann::json(*r.cores) : nlohmann::json(nullptr);
  }
  return out;
}

}  // namespace gridfree
