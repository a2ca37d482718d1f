// SPDX-License-Identifier: GPL-3.0-or-later
// Project version, source revision and build type, as recorded at build time
// (the version comes from project(... VERSION) in CMakeLists.txt).
#pragma once

#include <string>

namespace gridfree {

const char* project_version();   // "0.2.0"
const char* source_revision();   // short git sha, or "unknown"
const char* build_type();        // CMAKE_BUILD_TYPE ("Release", ...), or "unknown"

// "gridfree 0.2.0 (abcdef1234)": what results record.
std::string version_string();

// "<program> 0.2.0 (commit abcdef1234, Release build)": what
// `program --version` prints.
std::string program_version_string(const std::string& program);

// The part of the version that changes results: part of every job_hash.
// Bump kSolverVersion whenever a change alters what the worker computes.
inline constexpr const char* kSolverVersion = "gridfree-solver/5";

}  // namespace gridfree
