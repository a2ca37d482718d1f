// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm settings: profile reading, merging, validation (see slurm_settings.h).
#include "exec/slurm_settings.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include "core/command_suggestion.h"
#include "core/input_error.h"
#include "study/slurm_block.h"

namespace gridfree {
namespace {

std::string text_of(const nlohmann::json& v, const std::string& field) {
  if (!v.is_string()) throw InputError(field, "must be a string");
  return v.get<std::string>();
}

double number_of(const nlohmann::json& v, const std::string& field) {
  if (!v.is_number()) throw InputError(field, "must be a number");
  return v.get<double>();
}

int int_of(const nlohmann::json& v, const std::string& field) {
  if (!v.is_number_integer()) throw InputError(field, "must be an integer");
  return v.get<int>();
}

std::vector<std::string> lines_of(const nlohmann::json& v, const std::string& field) {
  if (!v.is_array()) throw InputError(field, "must be an array of strings");
  std::vector<std::string> out;
  for (const auto& x : v) out.push_back(text_of(x, field + "[]"));
  return out;
}

}  // namespace

SlurmSettings slurm_settings_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where, "must be a JSON object");
  SlurmSettings s;
  for (const auto& [key, v] : j.items()) {
    const std::string f = where + "." + key;
    if (key == "partition") s.partition = text_of(v, f);
    else if (key == "account") s.account = text_of(v, f);
    else if (key == "qos") s.qos = text_of(v, f);
    else if (key == "constraint") s.constraint = text_of(v, f);
    else if (key == "time_minutes") s.time_minutes = number_of(v, f);
    else if (key == "mem_mb") s.mem_mb = number_of(v, f);
    else if (key == "cpus_per_task") s.cpus_per_task = int_of(v, f);
    else if (key == "sbatch_args") s.sbatch_args = lines_of(v, f);
    else if (key == "setup") s.setup = lines_of(v, f);
    else if (key == "runs_dir") s.runs_dir = text_of(v, f);
    else if (key == "max_queued") s.max_queued = int_of(v, f);
    else if (key == "array_size") s.array_size = int_of(v, f);
    else if (key == "poll_s") s.poll_s = number_of(v, f);
    else if (key == "margin") s.margin = number_of(v, f);
    else {
      std::string valid;
      for (const auto& k : slurm_setting_keys()) valid += (valid.empty() ? "" : ", ") + k;
      const std::string near = nearest_name(key, slurm_setting_keys());
      throw InputError(where + "." + key.substr(0, 64),
                       "unknown setting" + (near.empty() ? std::string() : "; did you mean '" + near + "'?") +
                           " (valid: " + valid + ")");
    }
  }
  validate(s);
  return s;
}

SlurmSettings read_slurm_profile(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError("--slurm-profile", "cannot read '" + file.string() + "'");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("--slurm-profile", "'" + file.string() + "' is not valid JSON: " + e.what());
  }
  return slurm_settings_from_json(j, "slurm-profile");
}

SlurmSettings merge(const SlurmSettings& base, const SlurmSettings& over) {
  SlurmSettings m = base;
  auto pick = [](auto& dst, const auto& src) {
    if (!src.empty()) dst = src;
  };
  pick(m.partition, over.partition);
  pick(m.account, over.account);
  pick(m.qos, over.qos);
  pick(m.constraint, over.constraint);
  pick(m.sbatch_args, over.sbatch_args);
  pick(m.setup, over.setup);
  if (!over.runs_dir.empty()) m.runs_dir = over.runs_dir;
  if (over.time_minutes) m.time_minutes = over.time_minutes;
  if (over.mem_mb) m.mem_mb = over.mem_mb;
  if (over.cpus_per_task) m.cpus_per_task = over.cpus_per_task;
  if (over.max_queued) m.max_queued = over.max_queued;
  if (over.array_size) m.array_size = over.array_size;
  if (over.poll_s) m.poll_s = over.poll_s;
  if (over.margin != SlurmSettings{}.margin) m.margin = over.margin;
  return m;
}

void validate(const SlurmSettings& s) {
  auto positive = [](const std::optional<double>& v, const char* field) {
    if (v && !(std::isfinite(*v) && *v > 0)) throw InputError(field, "must be a positive number");
  };
  positive(s.time_minutes, "--time");
  positive(s.mem_mb, "--mem");
  positive(s.poll_s, "--poll");
  if (s.cpus_per_task && *s.cpus_per_task < 1) throw InputError("--cpus-per-task", "must be at least 1");
  if (s.max_queued && *s.max_queued < 1) throw InputError("--max-queued", "must be at least 1");
  if (s.array_size && (*s.array_size < 1 || *s.array_size > 100000))
    throw InputError("--array-size", "must be between 1 and 100000");
  if (!(std::isfinite(s.margin) && s.margin >= 1)) throw InputError("margin", "must be at least 1");
  for (const auto& a : s.sbatch_args)
    if (const auto option = sbatch_option_set_by_gridfree(a); !option.empty())
      throw InputError("--sbatch-arg", "'" + a.substr(0, 64) + "' passes " + option +
                                           ", which gridfree sets itself (refused: --array, --output, --error, "
                                           "--job-name, --parsable, --signal, --requeue, --no-requeue, "
                                           "--cpus-per-task, --wrap and their short forms)");
}

EnvLookup process_environment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* v = std::getenv(name.c_str());
    if (v == nullptr) return std::nullopt;
    return std::string(v);
  };
}

SbatchEnvironment sbatch_environment(const EnvLookup& env) {
  SbatchEnvironment e;
  auto first_set = [&](std::initializer_list<const char*> names) -> std::optional<EnvSetting> {
    for (const char* n : names)
      if (auto v = env(n); v && !v->empty()) return EnvSetting{n, *v};
    return std::nullopt;
  };
  e.time = first_set({"SBATCH_TIMELIMIT"});
  e.memory = first_set({"SBATCH_MEM_PER_NODE", "SBATCH_MEM_PER_CPU", "SBATCH_MEM_PER_GPU"});
  for (const char* n : {"SBATCH_PARTITION", "SBATCH_ACCOUNT", "SBATCH_QOS", "SBATCH_CONSTRAINT"})
    if (auto v = first_set({n})) e.others.push_back(*v);
  return e;
}

std::optional<double> slurm_time_minutes(const std::string& text) {
  // Numbers separated by ':' after an optional "D-".
  double days = 0;
  std::string rest = text;
  const bool has_days = rest.find('-') != std::string::npos;
  auto number = [](const std::string& t) -> std::optional<double> {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stod(t);
  };
  if (has_days) {
    const auto d = number(rest.substr(0, rest.find('-')));
    if (!d) return std::nullopt;
    days = *d;
    rest = rest.substr(rest.find('-') + 1);
  }
  std::vector<double> parts;
  std::size_t start = 0;
  for (;;) {
    const auto end = rest.find(':', start);
    const auto v = number(rest.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (!v) return std::nullopt;
    parts.push_back(*v);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (parts.size() > 3) return std::nullopt;
  if (has_days) {  // D-HH, D-HH:MM, D-HH:MM:SS
    const double h = parts[0], m = parts.size() > 1 ? parts[1] : 0, sec = parts.size() > 2 ? parts[2] : 0;
    return days * 1440 + h * 60 + m + sec / 60;
  }
  if (parts.size() == 1) return parts[0];                       // MM
  if (parts.size() == 2) return parts[0] + parts[1] / 60;       // MM:SS
  return parts[0] * 60 + parts[1] + parts[2] / 60;              // HH:MM:SS
}

}  // namespace gridfree
