// SPDX-License-Identifier: GPL-3.0-or-later
// The external-solver job (docs/INTERFACE.md "External solvers",
// docs/EXTERNAL.md): the part of a job document under /case/external, read
// and checked by parse_external_job.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

// How one quantity is read from the finished case folder: either the last
// data row's `column` of the newest file matching `file`, or the first
// capture group of the last line of `log` that `regex` matches.
struct QuantitySpec {
  std::string name;
  std::string units;
  std::string description;
  std::string file;  // glob relative to case/; "" when read from a log
  int column = -1;
  std::string log;   // path (or glob) relative to case/; "stdout"/"stderr": the command's own streams
  std::string regex;
};

struct ResidualSpec {
  std::string log;
  std::string regex;
  double tolerance = 0;
};

struct CollectSpec {
  std::vector<QuantitySpec> quantities;
  std::vector<std::string> failure_patterns;  // ECMAScript regexes, searched line by line
  // Further files (paths or globs relative to case/) the failure patterns
  // are searched in, besides stdout, stderr, the collected logs and every
  // log.* / *.log file of case/ (docs/EXTERNAL.md "Collection").
  std::vector<std::string> logs;
  std::optional<ResidualSpec> residual;
  std::optional<double> steady_tolerance;
};

struct ExternalJob {
  std::string name;
  std::filesystem::path template_dir;  // absolute (relative ones against the job file's folder)
  std::string template_sha256;
  std::vector<std::string> render;     // relative paths inside the template
  std::vector<std::pair<std::string, double>> variables;
  // Text placeholders: the case's constants and the series' factor levels,
  // written verbatim (docs/EXTERNAL.md "Factors, designs and ensembles").
  std::vector<std::pair<std::string, std::string>> levels;
  std::vector<std::string> setup;
  std::vector<std::string> command;    // argv
  std::string version;
  CollectSpec collect;
  std::optional<double> grid_h;        // numerics.grid.h, echoed into the result
  std::optional<double> grid_cells;    // numerics.grid.cells
};

// True when the job document's case is an external one (/case/external present).
bool is_external_job(const nlohmann::json& doc);

// The external job, every problem collected into one InputError whose
// `where` is the JSON pointer (/case/external/collect/quantities/ke/column).
ExternalJob parse_external_job(const nlohmann::json& doc, const std::filesystem::path& job_dir);

}  // namespace gridfree
