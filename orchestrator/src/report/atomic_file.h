// Writes a file atomically: the content goes to a temporary file in the same
// folder, which is then renamed over the target, so a reader never sees a
// half-written report (rename within one file system is atomic on POSIX).
#pragma once

#include <filesystem>
#include <string_view>

namespace gridfree {

// Throws std::runtime_error (with the path and the reason) on failure; the
// temporary file is removed then. Temporary files of the same target left by
// a writer that was killed (its pid no longer exists) are removed first.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace gridfree
