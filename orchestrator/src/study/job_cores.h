// SPDX-License-Identifier: GPL-3.0-or-later
// The cores of one job (docs/ORCHESTRATOR.md "Cores"): a study's "cores"
// is an expression of `cells` (study/expression.h), e.g.
// "max(1, cells / 50000)"; a job gets
//
//   cores(job) = min(cap, max(1, floor(value at the job's cells)))
//
// where cap is the pool's cores (local: the machine's cores, or -j when
// larger) or Slurm's --cpus-per-task. Without the field every job gets the
// executor's threads per job, as before. Pure functions.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// A cap that never binds: the rule's own value (plan's listing, before the
// pool is known).
inline constexpr int kUncappedCores = 1 << 20;

// The variable the expression may read.
inline constexpr const char* kCoresVariable = "cells";

// A study definition's /cores as an expression: the string, or a whole
// number written as one ("" when the field is absent).
std::string study_cores_expression(const nlohmann::json& definition);

// Adds a problem at `where` when `text` does not parse or reads a name
// other than `cells`.
void check_cores_expression(const std::string& text, const std::string& where, ProblemList& problems);

// The expression's value at `cells` (not rounded); throws ExpressionError.
double cores_value(const std::string& text, double cells);

// cores(job) by the rule above; nullopt when the value is not a finite
// number (validation refuses such a study, so a running one never has it).
std::optional<int> job_cores(const std::string& text, double cells, int cap);

}  // namespace gridfree
