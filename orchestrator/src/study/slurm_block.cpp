// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm settings keys and sbatch words (see slurm_block.h).
#include "study/slurm_block.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace gridfree {
namespace {

struct SbatchOption {
  std::string_view long_name;
  char short_name;  // 0 = none
};

// The options gridfree passes itself (exec/slurm_script.cpp's sbatch_command,
// plus --wrap, which would replace the batch script).
constexpr std::array<SbatchOption, 10> kSetByGridfree = {{{"array", 'a'},
                                                          {"output", 'o'},
                                                          {"error", 'e'},
                                                          {"job-name", 'J'},
                                                          {"parsable", 0},
                                                          {"signal", 0},
                                                          {"requeue", 0},
                                                          {"no-requeue", 0},
                                                          {"cpus-per-task", 'c'},
                                                          {"wrap", 0}}};

// sbatch's short options that take a value: the rest of a cluster after
// one of them is that value ("-ofile"), not more flags.
constexpr std::string_view kShortWithValue = "AabCcDdeFGiJLMmNnopqStwx";

std::string shown(const SbatchOption& o) {
  std::string s = "--" + std::string(o.long_name);
  if (o.short_name != 0) s += std::string(" (-") + o.short_name + ")";
  return s;
}

// The long option name of "--name[=value]" ("" if the word is not one).
std::string_view long_name_of(std::string_view word) {
  if (word.size() < 3 || word.substr(0, 2) != "--") return {};
  return word.substr(2, word.find('=') == std::string_view::npos ? std::string_view::npos : word.find('=') - 2);
}

// The short option letters a word "-xyz" passes, up to the first that takes a value.
std::string short_flags_of(std::string_view word) {
  std::string out;
  if (word.size() < 2 || word[0] != '-' || word[1] == '-') return out;
  for (std::size_t i = 1; i < word.size(); ++i) {
    out += word[i];
    if (kShortWithValue.find(word[i]) != std::string_view::npos) break;
  }
  return out;
}

// `name` is `full` or an abbreviation of it getopt_long would accept (at
// least three letters, so that "--e" is left to sbatch's "ambiguous").
bool names(std::string_view name, std::string_view full) {
  return name == full || (name.size() >= 3 && full.substr(0, name.size()) == name);
}

bool sets(const std::vector<std::string>& words, std::initializer_list<std::string_view> long_names,
          char short_name) {
  return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
    const auto name = long_name_of(w);
    if (!name.empty())
      return std::any_of(long_names.begin(), long_names.end(), [&](std::string_view n) { return name == n; });
    return short_flags_of(w).find(short_name) != std::string::npos;
  });
}

}  // namespace

const std::vector<std::string>& slurm_setting_keys() {
  static const std::vector<std::string> keys = {"partition", "account",  "qos",      "constraint", "time_minutes",
                                                "mem_mb",    "cpus_per_task", "sbatch_args", "setup", "runs_dir",
                                                "max_queued", "array_size", "poll_s", "margin"};
  return keys;
}

std::string sbatch_option_set_by_gridfree(const std::string& word) {
  if (const auto name = long_name_of(word); !name.empty()) {
    for (const auto& o : kSetByGridfree)
      if (names(name, o.long_name)) return shown(o);
    return "";
  }
  for (char c : short_flags_of(word))
    for (const auto& o : kSetByGridfree)
      if (o.short_name != 0 && o.short_name == c) return shown(o);
  return "";
}

bool sbatch_words_set_time(const std::vector<std::string>& words) { return sets(words, {"time"}, 't'); }

bool sbatch_words_set_memory(const std::vector<std::string>& words) {
  return sets(words, {"mem", "mem-per-cpu", "mem-per-gpu"}, 0);
}

}  // namespace gridfree
