// SPDX-License-Identifier: GPL-3.0-or-later
// Scratch folders for tests that write files: <temp>/gridfree_<tag>_<pid>/<name>.
// Each call empties and recreates its folder; the program's whole
// <temp>/gridfree_<tag>_<pid> is removed when the test program exits, so a
// passing run leaves nothing behind (a crashed one leaves its files to look at).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace gridfree::test_support {

class ScratchRoot {
 public:
  explicit ScratchRoot(const std::string& tag)
      : path_(std::filesystem::temp_directory_path() / ("gridfree_" + tag + "_" + std::to_string(::getpid()))) {}
  ~ScratchRoot() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchRoot(const ScratchRoot&) = delete;
  ScratchRoot& operator=(const ScratchRoot&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// This program's scratch root (the first tag asked for names it).
inline const std::filesystem::path& scratch_root(const std::string& tag) {
  static const ScratchRoot root(tag);
  return root.path();
}

// A fresh, empty folder `name` under the scratch root.
inline std::filesystem::path fresh_scratch_dir(const std::string& tag, const std::string& name) {
  const auto dir = scratch_root(tag) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A path for a new SQLite database `name`.sqlite under the scratch root:
// no file there, nor its -wal and -shm.
inline std::filesystem::path fresh_db_path(const std::string& tag, const std::string& name) {
  const auto& dir = scratch_root(tag);
  std::filesystem::create_directories(dir);
  const auto db = dir / (name + ".sqlite");
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
  return db;
}

}  // namespace gridfree::test_support
