// SPDX-License-Identifier: GPL-3.0-or-later
// Writes a file atomically: the content goes to a temporary file in the same
// folder, which is then renamed over the target, so a reader never sees a
// half-written report (rename within one file system is atomic on POSIX).
#pragma once

#include <filesystem>
#include <string_view>

namespace gridfree {

// Throws std::runtime_error (with the path and the reason) on failure; the
// temporary file (".<name>.tmp-<pid>-<n>") is removed then.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

// Removes the temporary files in `dir` left by writers that were killed
// (kill -9) between writing and renaming: ".<name>.tmp-<pid>-<n>" whose
// process no longer exists, and "<name>.pdf.tmp"/"<name>.png.tmp" of chart
// exports by older versions. One listing of the folder: called once per
// report write, not per file (which made a report write O(files²)).
void remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace gridfree
