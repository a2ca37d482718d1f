// SPDX-License-Identifier: GPL-3.0-or-later
// Run folders of jobs: size and removal (exec/run_folders.h).
#include "exec/run_folders.h"

#include <cctype>

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// Not empty, not a path, and not two hex digits (the name of a shard folder).
bool plain_hash(const std::string& h) {
  const bool shard_name = h.size() == 2 && std::isxdigit(static_cast<unsigned char>(h[0])) &&
                          std::isxdigit(static_cast<unsigned char>(h[1]));
  return !h.empty() && !shard_name && h.find('/') == std::string::npos && h.find('\\') == std::string::npos &&
         h.find("..") == std::string::npos;
}

// The folders a job's run may sit in: the flat layout's, then the sharded one.
std::vector<fs::path> candidate_folders(const fs::path& root, const std::string& h) {
  std::vector<fs::path> out{root / h};
  if (h.size() >= 3) out.push_back(root / h.substr(0, 2) / h);
  return out;
}

std::uintmax_t tree_bytes(const fs::path& dir) {
  std::uintmax_t total = 0;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    std::error_code size_ec;
    if (it->is_regular_file(size_ec) && !it->is_symlink(size_ec)) {
      const auto n = it->file_size(size_ec);
      if (!size_ec) total += n;
    }
  }
  return total;
}

}  // namespace

std::uintmax_t run_folder_bytes(const fs::path& runs_root, const std::string& job_hash) {
  if (!plain_hash(job_hash)) return 0;
  std::uintmax_t total = 0;
  for (const auto& dir : candidate_folders(runs_root, job_hash)) total += tree_bytes(dir);
  return total;
}

void remove_run_folder(const fs::path& runs_root, const std::string& job_hash) {
  if (!plain_hash(job_hash)) return;
  std::error_code ec;
  for (const auto& dir : candidate_folders(runs_root, job_hash)) fs::remove_all(dir, ec);
  if (job_hash.size() >= 3) {
    const fs::path shard = runs_root / job_hash.substr(0, 2);
    if (fs::is_directory(shard, ec) && fs::is_empty(shard, ec)) fs::remove(shard, ec);  // only when empty
  }
}

void remove_run_folders(const fs::path& runs_root, const std::vector<std::string>& job_hashes) {
  for (const auto& h : job_hashes) remove_run_folder(runs_root, h);
}

}  // namespace gridfree
