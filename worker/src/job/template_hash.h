// SPDX-License-Identifier: GPL-3.0-or-later
// Identity of an external solver's template folder (docs/EXTERNAL.md).
//
// template_sha256(dir) is the SHA-256 (hex) of the folder's regular files,
// taken in order of their relative paths ('/'-separated, byte order), each
// contributing
//     relpath \0 ("x" if owner-executable else "-") \0 size (decimal) \0 contents
// so an edit of a file's contents, its executable bit or its name changes
// the hash, and a copy of the folder elsewhere hashes alike. Directories
// contribute only through their files (an empty folder is not part of it).
// A symlink to a file inside the folder counts as that file's contents under
// the link's own path (the driver's copy dereferences it the same way).
// Refused with std::runtime_error naming the path: a symlink whose target
// lies outside the folder or does not exist, a symlink to a directory, any
// other non-regular file (fifo, socket, device), and an unreadable file.
#pragma once

#include <filesystem>
#include <string>

namespace gridfree {

std::string template_sha256(const std::filesystem::path& dir);

}  // namespace gridfree
