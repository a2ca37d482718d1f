// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/external_driver.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/input_error.h"
#include "external/case_glob.h"
#include "external/process_run.h"
#include "external/quantity_read.h"
#include "external/render.h"
#include "job/template_hash.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<std::string> driver_read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void driver_write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// "stdout"/"stderr": the command's streams; anything else: a path or glob in case/.
std::optional<fs::path> driver_log_file(const fs::path& case_dir, const std::string& log) {
  if (log == "stdout") return case_dir / kCaseStdout;
  if (log == "stderr") return case_dir / kCaseStderr;
  return newest_case_match(case_dir, log);
}

std::string case_relative(const fs::path& case_dir, const fs::path& file) {
  return file.lexically_relative(case_dir).generic_string();
}

// The last `lines` non-empty lines of a text, joined by " | ", at most
// kStderrTailChars characters (the end kept): the tail of a command's stderr.
constexpr std::size_t kStderrTailChars = 400;
std::string last_nonempty_lines(const std::string& text, int lines) {
  std::vector<std::string> found;
  std::size_t end = text.size();
  while (end > 0 && static_cast<int>(found.size()) < lines) {
    while (end > 0 && (text[end - 1] == '\n' || text[end - 1] == '\r' || text[end - 1] == ' ')) --end;
    if (end == 0) break;
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t from = start == std::string::npos ? 0 : start + 1;
    std::string line = text.substr(from, end - from);
    const std::size_t first = line.find_first_not_of(" \t");
    found.push_back(first == std::string::npos ? line : line.substr(first));
    end = from;
  }
  std::string out;
  for (auto it = found.rbegin(); it != found.rend(); ++it) out += (out.empty() ? "" : " | ") + *it;
  if (out.size() > kStderrTailChars) out = "…" + out.substr(out.size() - kStderrTailChars);
  return out;
}

// Files of case/ (top level) that look like logs: log.* (OpenFOAM's
// log.blockMesh, log.icoFoam) or *.log, oldest first (the order the
// programs of a command wrote them; ties by name).
std::vector<fs::path> case_log_files(const fs::path& case_dir) {
  std::vector<std::pair<fs::file_time_type, fs::path>> found;
  std::error_code ec;
  for (auto it = fs::directory_iterator(case_dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::error_code type_ec;
    if (!it->is_regular_file(type_ec)) continue;
    const std::string name = it->path().filename().string();
    const bool log_like = name.rfind("log.", 0) == 0 ||
                          (name.size() > 4 && name.compare(name.size() - 4, 4, ".log") == 0);
    if (log_like) found.emplace_back(it->last_write_time(type_ec), it->path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& [t, p] : found) out.push_back(p);
  return out;
}

QuantitySighting sight_quantity(const QuantitySpec& q, const fs::path& case_dir) {
  QuantitySighting s;
  s.name = q.name;
  const bool by_file = !q.file.empty();
  const std::string pattern = by_file ? q.file : q.log;
  const auto file = by_file ? newest_case_match(case_dir, q.file) : driver_log_file(case_dir, q.log);
  s.source = file ? case_relative(case_dir, *file) : pattern;
  const auto text = file ? driver_read_text(*file) : std::nullopt;
  if (!text) {
    s.problem = "no file matches " + pattern + " in the case folder";
    return s;
  }
  const QuantityRecords r = by_file ? read_column(*text, q.column)
                                    : read_regex(*text, std::regex(q.regex, std::regex::ECMAScript), q.regex);
  s.last = r.last;
  s.previous = r.previous;
  if (!r.problem.empty()) s.problem = r.problem + " in " + s.source;
  return s;
}

// The command's own result file: its verdict and quantities (name → sighting).
std::optional<DriverVerdict> sight_own_result(const fs::path& case_dir, std::vector<QuantitySighting>& quantities) {
  const auto text = driver_read_text(case_dir / kCaseOwnResult);
  if (!text) return std::nullopt;
  const json doc = json::parse(*text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object())
    return DriverVerdict{"failed", std::string(kCaseOwnResult) + " is not a JSON object"};
  if (doc.contains("quantities") && doc.at("quantities").is_object())
    for (const auto& [name, v] : doc.at("quantities").items()) {
      QuantitySighting s;
      s.name = name;
      s.source = kCaseOwnResult;
      if (v.is_number()) s.last = v.get<double>();
      else if (v.is_string()) s.last = parse_record_number(v.get<std::string>());
      if (!s.last) s.problem = "not a number in " + std::string(kCaseOwnResult);
      quantities.push_back(s);
    }
  DriverVerdict verdict{"converged", ""};
  if (doc.contains("status") && doc.at("status").is_string()) verdict.status = doc.at("status").get<std::string>();
  if (doc.contains("reason") && doc.at("reason").is_string()) verdict.reason = doc.at("reason").get<std::string>();
  static const std::set<std::string> kKnown = {"converged", "not_converged", "diverged", "failed"};
  if (!kKnown.count(verdict.status)) verdict = {"failed", "unknown status \"" + verdict.status + "\""};
  return verdict;
}

// The failure patterns are searched in stdout, stderr, the files named in
// collect.logs, the logs of the quantities and the residual, then every
// other log file of case/ (case_log_files); the first matching line of the
// first file with one is reported.
std::optional<FailureSighting> sight_failure(const ExternalJob& job, const fs::path& case_dir) {
  if (job.collect.failure_patterns.empty()) return std::nullopt;
  std::vector<std::regex> patterns;
  for (const auto& p : job.collect.failure_patterns) patterns.emplace_back(p, std::regex::ECMAScript);
  std::vector<std::string> logs = {"stdout", "stderr"};
  logs.insert(logs.end(), job.collect.logs.begin(), job.collect.logs.end());
  for (const auto& q : job.collect.quantities)
    if (!q.log.empty()) logs.push_back(q.log);
  if (job.collect.residual) logs.push_back(job.collect.residual->log);
  std::vector<fs::path> files;
  for (const auto& log : logs)
    if (const auto file = driver_log_file(case_dir, log)) files.push_back(*file);
  for (const auto& file : case_log_files(case_dir)) files.push_back(file);
  std::set<fs::path> seen;
  for (const auto& file : files) {
    if (!seen.insert(file).second) continue;
    const auto text = driver_read_text(file);
    if (!text) continue;
    if (const auto hit = find_pattern(*text, patterns, job.collect.failure_patterns))
      return FailureSighting{hit->pattern, case_relative(case_dir, file), hit->line, hit->text};
  }
  return std::nullopt;
}

json number_or_null_json(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json external_result(const ExternalJob& job, const ExternalRunOptions& options, const ExternalSightings& s,
                     const ExternalClassification& c, double wall_s, double cpu_s, double rss_mb) {
  json quantities = json::object();
  for (const auto& q : s.quantities)
    if (q.last) quantities[q.name] = number_or_null_json(*q.last);
  json extra = {{"external_version", job.version}, {"case_dir", kCaseFolder}};
  if (s.exit) {
    extra["exit_code"] = s.exit->code ? json(*s.exit->code) : json(nullptr);
    if (s.exit->signal) extra["signal"] = signal_name(*s.exit->signal);
  }
  if (job.grid_cells) extra["cells"] = *job.grid_cells;
  json r = {{"schema", "gridfree/result/1"},
            {"job_hash", options.job_hash},
            {"status", c.status},
            {"outcome", c.outcome},
            {"reason", c.reason},
            {"srq", {{"dp_star", nullptr}}},
            {"quantities", quantities},
            {"timing", {{"wall_s", wall_s}, {"cpu_s", cpu_s}}},
            {"memory", {{"peak_rss_mb", rss_mb}}},
            {"extra", extra},
            {"version", options.worker_version}};
  if (job.grid_h) r["grid"] = {{"h", *job.grid_h}};
  return r;
}

json failed_before_running(const ExternalJob& job, const ExternalRunOptions& options, const std::string& reason) {
  ExternalSightings none;
  return external_result(job, options, none, {"failed", "failed", reason}, 0, 0, 0);
}

void copy_template(const fs::path& from, const fs::path& to) {
  fs::create_directories(to);
  for (auto it = fs::recursive_directory_iterator(from); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path target = to / it->path().lexically_relative(from);
    if (it->is_directory()) fs::create_directories(target);
    else fs::copy_file(it->path(), target, fs::copy_options::overwrite_existing);  // a symlink: its file
  }
}

}  // namespace

ExternalSightings gather_sightings(const ExternalJob& job, const fs::path& case_dir, const std::optional<ExternalExit>& exit) {
  ExternalSightings s;
  s.exit = exit;
  if (const auto err = driver_read_text(case_dir / kCaseStderr)) s.stderr_tail = last_nonempty_lines(*err, 3);
  s.failure = sight_failure(job, case_dir);
  std::vector<QuantitySighting> own;
  s.driver = sight_own_result(case_dir, own);
  for (const auto& q : job.collect.quantities) {
    const bool from_own = std::any_of(own.begin(), own.end(), [&](const auto& o) { return o.name == q.name; });
    if (!from_own) s.quantities.push_back(sight_quantity(q, case_dir));
  }
  s.quantities.insert(s.quantities.end(), own.begin(), own.end());
  if (job.collect.residual) {
    const auto& spec = *job.collect.residual;
    const auto file = driver_log_file(case_dir, spec.log);
    ResidualSighting r;
    r.tolerance = spec.tolerance;
    r.source = file ? case_relative(case_dir, *file) : spec.log;
    const auto text = file ? driver_read_text(*file) : std::nullopt;
    if (!text) {
      r.problem = "no file matches " + spec.log + " in the case folder";
    } else {
      const auto rec = read_regex(*text, std::regex(spec.regex, std::regex::ECMAScript), spec.regex);
      r.last = rec.last;
      if (!rec.problem.empty()) r.problem = rec.problem + " in " + r.source;
    }
    s.residual = r;
  }
  s.steady_tolerance = job.collect.steady_tolerance;
  return s;
}

void prepare_external_case(const ExternalJob& job, const fs::path& run_dir, int cores) {
  const fs::path case_dir = run_dir / kCaseFolder;
  RenderTexts variables;  // numbers as render_number writes them, factor levels verbatim
  for (const auto& [name, value] : job.variables) variables.emplace_back(name, render_number(value));
  variables.insert(variables.end(), job.levels.begin(), job.levels.end());
  const bool has_cores = std::any_of(variables.begin(), variables.end(), [](const auto& v) { return v.first == "cores"; });
  if (!has_cores) variables.emplace_back("cores", render_number(cores));
  fs::remove_all(case_dir);
  copy_template(job.template_dir, case_dir);
  for (std::size_t i = 0; i < job.render.size(); ++i) {
    const std::string where = "/case/external/render/" + std::to_string(i);
    const auto text = driver_read_text(job.template_dir / job.render[i]);
    if (!text || fs::is_directory(job.template_dir / job.render[i]))
      throw InputError(where, job.render[i] + " is not a file in the template folder");
    try {
      driver_write_text(case_dir / job.render[i], render_placeholders(*text, variables, job.render[i]));
    } catch (const UndefinedPlaceholder& e) {
      std::string known;
      for (const auto& [name, value] : variables) known += (known.empty() ? "" : ", ") + name;
      throw InputError(where, std::string(e.what()) + " (variables: " + (known.empty() ? "none" : known) + ")");
    }
  }
}

ExternalRunEnd run_external_job(const ExternalJob& job, const ExternalRunOptions& options) {
  ExternalRunEnd end;
  std::string now_hash;
  try {
    now_hash = template_sha256(job.template_dir);
  } catch (const std::runtime_error& e) {
    end.result = failed_before_running(job, options, e.what());
    return end;
  }
  if (now_hash != job.template_sha256) {
    end.result = failed_before_running(job, options,
                                       "template changed since the job was planned (" + job.template_dir.string() +
                                           ": sha256 " + now_hash.substr(0, 12) + ", planned " +
                                           job.template_sha256.substr(0, 12) + "); plan the study again");
    return end;
  }
  prepare_external_case(job, options.run_dir, options.cores);
  const fs::path case_dir = options.run_dir / kCaseFolder;
  if (options.stop_requested && options.stop_requested()) {  // asked to stop while copying
    end.stopped = true;
    return end;
  }
  CommandLaunch launch{job.setup, job.command, case_dir, case_dir / kCaseStdout, case_dir / kCaseStderr};
  const CommandEnd ran =
      run_command_watched(launch, CommandWatch{options.stop_requested, options.on_tick, options.stop_grace_s});
  if (ran.stopped) {
    end.stopped = true;
    return end;
  }
  const json record = {{"exit_code", ran.exit_code ? json(*ran.exit_code) : json(nullptr)},
                       {"signal", ran.signal ? json(*ran.signal) : json(nullptr)},
                       {"wall_s", ran.wall_s},
                       {"cpu_s", ran.cpu_s},
                       {"peak_rss_mb", ran.peak_rss_mb}};
  driver_write_text(case_dir / kCaseExitRecord, record.dump() + "\n");
  const ExternalSightings s = gather_sightings(job, case_dir, ExternalExit{ran.exit_code, ran.signal});
  const ExternalClassification c = classify_external(s);
  end.result = external_result(job, options, s, c, ran.wall_s, ran.cpu_s, ran.peak_rss_mb);
  end.converged = c.status == "converged";
  return end;
}

json collect_external_job(const ExternalJob& job, const ExternalRunOptions& options) {
  const fs::path case_dir = options.run_dir / kCaseFolder;
  std::error_code ec;
  if (!fs::is_directory(case_dir, ec))
    throw InputError(case_dir.string(), "no case folder to collect from (run the job first)");
  std::optional<ExternalExit> exit;
  double wall_s = 0, cpu_s = 0, rss_mb = 0;
  if (const auto text = driver_read_text(case_dir / kCaseExitRecord)) {
    const json rec = json::parse(*text, nullptr, false);
    if (rec.is_object()) {
      ExternalExit e;
      if (rec.value("exit_code", json()).is_number_integer()) e.code = rec.at("exit_code").get<int>();
      if (rec.value("signal", json()).is_number_integer()) e.signal = rec.at("signal").get<int>();
      exit = e;
      wall_s = rec.value("wall_s", 0.0);
      cpu_s = rec.value("cpu_s", 0.0);
      rss_mb = rec.value("peak_rss_mb", 0.0);
    }
  }
  const ExternalSightings s = gather_sightings(job, case_dir, exit);
  return external_result(job, options, s, classify_external(s), wall_s, cpu_s, rss_mb);
}

}  // namespace gridfree
