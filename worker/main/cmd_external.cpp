// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker solve JOB.json -o RESULT.json   (a job with /case/external)
// gridfree-worker collect JOB.json -o RESULT.json [--run-dir DIR]
//
// solve: runs the external driver (external/external_driver.h) in the job
// file's folder (the run folder: case/ goes there). Exit codes as for the
// gas solver: 0 converged; 3 not converged, diverged or failed (result
// written, with the reason); 2 invalid job (nothing written); 130 stopped by
// SIGTERM/SIGINT (forwarded to the command; no result). --progress FILE gets
// {"elapsed_s", "pid", "updated_unix_s", "external": true} every ~2 s.
// The --threads in effect is the template's @@cores@@ (docs/EXTERNAL.md
// "Cores and MPI").
// collect: the result from an existing case/ without running anything
// (after the study's collect section changed), same exit codes.
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include <spdlog/spdlog.h>

#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "core/version.h"
#include "external/external_driver.h"
#include "job/job_hash.h"
#include "job/job_spec.h"
#include "output_path.h"
#include "stop_request.h"

namespace gridfree::worker_cli {
namespace {

void write_external_text(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

std::filesystem::path external_run_dir(const std::filesystem::path& job_path) {
  return job_path.has_parent_path() ? job_path.parent_path() : std::filesystem::path(".");
}

int emit_external_result(const nlohmann::json& result, const std::string& output) {
  const std::string status = result.at("status").get<std::string>();
  if (status == "converged") spdlog::info("converged: {}", result.at("reason").get<std::string>());
  else spdlog::warn("{}: {}", status, result.at("reason").get<std::string>());
  const std::string text = result.dump(2) + "\n";
  if (output.empty()) std::cout << text << std::flush;
  else write_external_text(output, text);
  return to_int(status == "converged" ? ExitCode::kOk : ExitCode::kNotConverged);
}

struct CollectCommandOptions {
  std::string job_file;
  std::string output;
  std::string run_dir;
  bool quiet = false;
};

int run_collect(const CollectCommandOptions& o) {
  if (o.quiet) spdlog::set_level(spdlog::level::warn);
  check_output_path("-o", o.output);
  const std::filesystem::path job_path(o.job_file);
  const nlohmann::json doc = read_json_file(job_path);
  if (!is_external_job(doc)) throw InputError("/case/external", "collect reads external jobs only");
  const ExternalJob job = parse_external_job(doc, external_run_dir(job_path));
  ExternalRunOptions options;
  options.run_dir = o.run_dir.empty() ? external_run_dir(job_path) : std::filesystem::path(o.run_dir);
  options.job_hash = job_hash(doc);
  options.worker_version = version_string();
  return emit_external_result(collect_external_job(job, options), o.output);
}

}  // namespace

int run_external_solve(const std::filesystem::path& job_path, const nlohmann::json& doc, const std::string& output,
                       const std::string& progress_file, int cores) {
  // From here on a stop request is a flag (a SIGTERM while the template is
  // copied must not kill the worker half-way; the driver checks the flag
  // before it starts the command).
  install_stop_handlers();
  const std::filesystem::path run_dir = external_run_dir(job_path);
  const ExternalJob job = parse_external_job(doc, run_dir);
  ExternalRunOptions options;
  options.run_dir = run_dir;
  options.job_hash = job_hash(doc);
  options.worker_version = version_string();
  options.cores = cores;
  options.stop_requested = [] { return stop_requested(); };
  options.on_tick = [&progress_file](double elapsed) {
    if (progress_file.empty()) return;
    const nlohmann::json p = {
        {"elapsed_s", elapsed},
        {"pid", static_cast<long long>(::getpid())},
        {"external", true},
        {"updated_unix_s",
         std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count()}};
    try {
      write_external_text(progress_file, p.dump() + "\n");
    } catch (const std::exception& e) {
      spdlog::warn("progress file: {}", e.what());
    }
  };
  spdlog::info("running {} ({}) in {}", job.name.empty() ? "the external case" : job.name,
               job.command.empty() ? "" : job.command[0], (run_dir / kCaseFolder).string());
  const ExternalRunEnd end = run_external_job(job, options);
  if (end.stopped) {
    spdlog::warn("stopped: the command was sent SIGTERM; no result written");
    return to_int(ExitCode::kInterrupted);
  }
  return emit_external_result(end.result, output);
}

void add_collect_command(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<CollectCommandOptions>();
  auto* sub = app.add_subcommand(
      "collect", "re-read an external job's finished case/ folder into a result, without running it again");
  sub->add_option("job", opts->job_file, "job JSON file (with case.external)")->required();
  sub->add_option("-o,--output", opts->output, "result JSON file (default: stdout)");
  sub->add_option("--run-dir", opts->run_dir, "the run folder holding case/ (default: the job file's folder)");
  sub->add_flag("-q,--quiet", opts->quiet, "warnings and errors only");
  sub->callback([opts, &exit_code] { exit_code = run_collect(*opts); });
}

}  // namespace gridfree::worker_cli
