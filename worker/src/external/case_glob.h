// SPDX-License-Identifier: GPL-3.0-or-later
// Finding a quantity's file in the case folder: a glob relative to case/
// with `*` and `?` inside one path component, `[...]` sets, and `**` for
// any number of folders (docs/EXTERNAL.md "Collection").
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace gridfree {

// Whether the '/'-separated relative path matches the pattern (pure).
bool case_glob_match(const std::string& pattern, const std::string& relative_path);

// The newest (latest modification time; ties: the greatest path) regular
// file under `root` whose path relative to `root` matches `pattern`.
std::optional<std::filesystem::path> newest_case_match(const std::filesystem::path& root, const std::string& pattern);

}  // namespace gridfree
