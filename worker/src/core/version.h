// SPDX-License-Identifier: GPL-3.0-or-later
// Project version and source revision, as recorded at build time.
#pragma once

#include <string>

namespace gridfree {

const char* project_version();   // "0.1.0"
const char* source_revision();   // short git sha, or "unknown"

// "gridfree 0.1.0 (abcdef1234)": what --version prints and results record.
std::string version_string();

// "<program> 0.1.0 (abcdef1234)": what `program --version` prints.
std::string program_version_string(const std::string& program);

// The part of the version that changes results: part of every job_hash.
// Bump kSolverVersion whenever a change alters what the worker computes.
inline constexpr const char* kSolverVersion = "gridfree-solver/5";

}  // namespace gridfree
