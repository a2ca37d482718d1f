// Slurm settings: profile reading, merging, validation (see slurm_settings.h).
#include "exec/slurm_settings.h"

#include <cmath>
#include <fstream>
#include <set>

#include "core/input_error.h"

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
    else
      throw InputError(f, "unknown setting; valid: partition, account, qos, constraint, time_minutes, mem_mb, "
                          "cpus_per_task, sbatch_args, setup, runs_dir, max_queued, array_size, poll_s, margin");
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
    if (a.rfind("--array", 0) == 0 || a.rfind("--output", 0) == 0 || a.rfind("--parsable", 0) == 0)
      throw InputError("--sbatch-arg", "'" + a + "' is set by gridfree itself");
}

}  // namespace gridfree
