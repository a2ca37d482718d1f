// SPDX-License-Identifier: GPL-3.0-or-later
// External cases (docs/INTERFACE.md §3 "External cases", docs/EXTERNAL.md
// "The study"): a case run by another code. The study gives a template
// folder, the files of it to render (@@name@@ placeholders), grid variables
// (study "grids": {"variables": {...}}) and derived variables as
// expressions (study/expression.h), the spacing h as an expression, the
// command, the code's version and how to collect each quantity. Each
// (case × grid) is one job (the external job document, docs/INTERFACE.md
// §2); each (case × quantity) one series.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// The placeholder the driver fills with the job's cores (--threads of the
// worker, study/job_cores.h): defined in every rendered file, never a
// grid or derived variable's name.
inline constexpr const char* kExternalCoresPlaceholder = "cores";

// Grid variable name → its value on each grid (level i takes the i-th).
using GridVariables = std::map<std::string, std::vector<double>>;

struct ExternalQuantity {
  std::string name, units, description;
};

struct ExternalCase {
  std::filesystem::path template_dir;   // absolute
  std::string template_sha256;          // job/template_hash.h, at validation
  std::vector<std::string> render;      // relative to the template
  std::map<std::string, std::string> variables;  // derived name → expression
  // Case constants: placeholder name → its text (a string verbatim, a number
  // as JSON writes it), e.g. an instance's snapshot file or seed.
  std::map<std::string, std::string> constants;
  std::string h_expression;             // h itself, or (volume/(cells))^(1/dim) spelt out
  std::string h_meaning;                // for reports: "h = 1/N" or "h = (V/cells)^(1/2), cells = N^2, V = 1"
  std::string cells_expression;         // "" when not given
  std::vector<std::string> setup, command;
  std::string version;                  // declared, or the version command's first line
  nlohmann::json collect;               // as written
  std::vector<ExternalQuantity> quantities;  // collect.quantities, by name
  std::optional<double> cpu_s_per_cell, mb_per_cell;
};

// One grid of an external case: every variable's value, h and cells.
struct ExternalGrid {
  std::map<std::string, double> variables;  // grid and derived variables
  double h = 0;
  std::optional<double> cells;
};

// Reads /cases/NAME/external (`at` is that pointer; the schema has been
// checked): every problem is added with its pointer (template folder
// missing, render file missing, undefined @@name@@ with file and line,
// expression not finite or h not distinct on some grid, failing version
// command). nullopt when a problem was found.
// `text_placeholders` are further names the rendered files may hold (the
// study's factors, study/external_factors.h).
std::optional<ExternalCase> parse_external_case(const nlohmann::json& ext, const std::string& at,
                                                const std::filesystem::path& base_dir,
                                                const GridVariables& grids, ProblemList& problems,
                                                const std::set<std::string>& text_placeholders = {});

// The placeholder names of the case's rendered files (files that cannot be
// read have none).
std::set<std::string> rendered_placeholders(const ExternalCase& c);

// h as one expression: the string itself, or (V / (cells))^(1/dim) spelt
// out for {"cells", "volume", "dim"}; `meaning` (if given) for reports.
std::string external_h_expression(const nlohmann::json& h, std::string* meaning = nullptr);

// The values on grid `level`. Throws ExpressionError (names the expression)
// or std::runtime_error (a cycle among derived variables).
ExternalGrid external_grid(const ExternalCase& c, const GridVariables& grids, std::size_t level);

// Number of grids (the common length of the variable lists; 0 when none).
std::size_t external_grid_count(const GridVariables& grids);

// The job document of docs/INTERFACE.md §2 for one grid (the case's
// `constants` in it when it has any); `levels` (the
// series' factor levels, rendered as text) are in it only when there are
// any, so a study without factors has the documents it always had.
nlohmann::json external_job_document(const ExternalCase& c, const std::string& case_name,
                                     const ExternalGrid& grid, std::size_t level,
                                     const std::map<std::string, std::string>& levels = {});

// The placeholders of a rendered file's text: (line, name) in order.
std::vector<std::pair<std::size_t, std::string>> placeholders_of(const std::string& text);

}  // namespace gridfree
