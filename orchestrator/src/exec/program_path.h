// SPDX-License-Identifier: GPL-3.0-or-later
// Finding programs on a PATH value (given, not read from the environment,
// so that tests pass their own): the Slurm executor checks its commands up
// front, before the database is touched (docs/ORCHESTRATOR.md "Slurm").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

// The first executable regular file `program` in the ':'-separated `path`
// (an empty entry is the current folder, as for execvp).
std::optional<std::filesystem::path> find_on_path(const std::string& program, const std::string& path);

// The programs of `programs` not found on `path`, in order.
std::vector<std::string> missing_programs(const std::vector<std::string>& programs, const std::string& path);

// The Slurm commands the executor cannot work without (sacct is optional:
// many small clusters run no slurmdbd).
inline const std::vector<std::string> kSlurmRequiredPrograms = {"sbatch", "squeue", "scancel"};

}  // namespace gridfree
