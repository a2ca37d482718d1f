// SPDX-License-Identifier: GPL-3.0-or-later
// Removing and measuring the run folders of jobs (exec/executor.h
// run_dir_for: <runs_root>/<2 hex>/<hash>, or <runs_root>/<hash> in the
// flat layout of older versions), for `gridfree gc` and `gridfree delete`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gridfree {

// Bytes of the regular files under the job's run folder (either layout;
// 0 when there is none).
std::uintmax_t run_folder_bytes(const std::filesystem::path& runs_root, const std::string& job_hash);

// Removes the job's run folder (either layout) and then its shard folder
// when that is left empty. A hash that is empty or not a plain file name
// is skipped. Errors are ignored (a folder already gone is no error).
void remove_run_folder(const std::filesystem::path& runs_root, const std::string& job_hash);

void remove_run_folders(const std::filesystem::path& runs_root, const std::vector<std::string>& job_hashes);

}  // namespace gridfree
