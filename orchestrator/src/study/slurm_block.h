// SPDX-License-Identifier: GPL-3.0-or-later
// The Slurm settings object's vocabulary (a study's "slurm" block and the
// --slurm-profile file, docs/ORCHESTRATOR.md "Slurm settings"): its keys,
// and what an extra sbatch word (sbatch_args, --sbatch-arg) sets. In study/
// so that `validate` checks a study's block with the same rules as the
// Slurm executor (exec/slurm_settings.h).
#pragma once

#include <string>
#include <vector>

namespace gridfree {

// The keys of a Slurm settings object, in the documented order.
const std::vector<std::string>& slurm_setting_keys();

// The sbatch option an extra word passes that gridfree sets itself, as
// "--output (-o)", or "" when it sets none. Long forms with or without
// "=value" and their unambiguous abbreviations (sbatch accepts "--out=x"),
// short forms alone, with their value attached ("-ofile") or in a cluster
// of flags ("-Ho"): --array/-a, --output/-o, --error/-e, --job-name/-J,
// --parsable, --signal, --requeue, --no-requeue, --cpus-per-task/-c,
// --wrap.
std::string sbatch_option_set_by_gridfree(const std::string& word);

// True when the words set the time limit (--time, -t) or the memory
// (--mem, --mem-per-cpu, --mem-per-gpu): the user's own value, so
// gridfree passes none of its own.
bool sbatch_words_set_time(const std::vector<std::string>& words);
bool sbatch_words_set_memory(const std::vector<std::string>& words);

}  // namespace gridfree
