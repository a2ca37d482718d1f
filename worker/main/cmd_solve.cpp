// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker solve JOB.json [-o RESULT.json] [--threads N] [--start nested|analytic]
//                       [--vtk DIR] [--max-memory SIZE] [--progress FILE]
//                       [--checkpoint FILE] [--resume FILE] [--bed-cache DIR] [-v|-q]
//
// Parses the job (relative paths against the job file's folder), solves it,
// and writes the result JSON atomically (temporary file + rename; stdout
// without -o). Exit codes (docs/INTERFACE.md §2): 0 converged; 3 not converged,
// diverged or failed deposition (result written, with the reason); 2 invalid
// input (nothing written); 1 internal error. --progress FILE: a small JSON
// (iteration, residuals, dp_star, elapsed, cells; docs/INTERFACE.md) rewritten
// atomically with every progress log line (≈ every 2 s) for `gridfree status`.
// SIGTERM/SIGINT: stop after the current outer iteration, write the state to
// --checkpoint FILE (if given) and exit 130 without a result; --resume FILE
// continues from such a checkpoint (flow/checkpoint.h). --bed-cache DIR:
// generated beds are read from and kept in DIR (job/bed_cache.h).
// A job with /case/external runs another CFD code instead (cmd_external.cpp,
// docs/EXTERNAL.md).
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/spdlog.h>

#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "external/external_job.h"
#include "flow/solve.h"
#include "job/job_spec.h"
#include "job/memory_estimate.h"
#include "job/result.h"
#include "output_path.h"
#include "stop_request.h"
#include "thread_count.h"

namespace gridfree::worker_cli {
namespace {

struct SolveCommandOptions {
  std::string job_file;
  std::string output;
  int threads = 0;  // 0 = OMP_NUM_THREADS, else all cores
  std::string vtk_dir;
  std::string max_memory;  // "" = physical memory
  std::string progress_file;
  std::string start = "nested";
  std::string checkpoint_file;
  std::string resume_file;
  std::string bed_cache;
  bool verbose = false;
  bool quiet = false;
};

// Writes text to `path` via a temporary file in the same folder + rename.
void write_atomically(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

// Refuses (exit 2) a job whose estimated memory exceeds --max-memory, or
// this machine's physical memory when the option is not given.
void check_memory(const JobSpec& job, const std::string& max_memory) {
  double limit = static_cast<double>(machine_memory_bytes());
  std::string source = "this machine's physical memory";
  if (!max_memory.empty()) {
    const auto parsed = parse_memory_size(max_memory);
    if (!parsed) throw InputError("--max-memory", "'" + max_memory.substr(0, 40) + "' is not a size like 8G or 512M");
    limit = *parsed;
    source = "--max-memory";
  }
  const double need = job_memory_estimate_bytes(job.numerics.cells);
  if (limit > 0 && need > limit)
    throw InputError("/numerics/grid", "the estimated memory " + memory_text(need) + " of " +
                                           std::to_string(job.numerics.cells[0]) + "x" +
                                           std::to_string(job.numerics.cells[1]) + "x" +
                                           std::to_string(job.numerics.cells[2]) + " cells exceeds " + source +
                                           " (" + memory_text(limit) + ")");
}

// Wall seconds of this process's outer iterations: the latest and the
// longest so far (both unknown until two iterations have been reported,
// since the first one's start is hidden behind the setup).
struct IterationTimes {
  std::optional<double> latest_s, longest_s;
};

nlohmann::json optional_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); }

nlohmann::json progress_json(const IterationReport& r, double elapsed, const IterationTimes& times,
                             const std::array<int, 3>& cells, int threads) {
  return {{"iteration", r.iteration},
          {"continuity", r.continuity},
          {"momentum", r.momentum},
          {"dp_star", r.qoi ? nlohmann::json(*r.qoi) : nlohmann::json(nullptr)},
          {"dp_star_change", r.qoi_change},
          {"elapsed_s", elapsed},
          {"iteration_s", optional_number(times.latest_s)},
          {"longest_iteration_s", optional_number(times.longest_s)},
          {"cells", {cells[0], cells[1], cells[2]}},
          {"threads", threads},
          {"pid", static_cast<long long>(::getpid())},
          {"updated_unix_s", std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count()}};
}

int run_solve(const SolveCommandOptions& o) {
  if (o.quiet) spdlog::set_level(spdlog::level::warn);
  else if (o.verbose) spdlog::set_level(spdlog::level::debug);
  else spdlog::set_level(spdlog::level::info);
  const int threads = use_thread_count(o.threads);
  // Keep freed work arrays in the heap: the outer iterations allocate
  // same-sized vectors over and over, and returning them to the kernel each
  // time costs page faults (measured: about a third of the CPU time).
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);

  // 1. Parse (throws InputError → exit 2, nothing written); a result that
  // could not be written is refused before solving.
  check_output_path("-o", o.output);
  const std::filesystem::path job_path(o.job_file);
  const nlohmann::json doc = read_json_file(job_path);
  if (is_external_job(doc)) return run_external_solve(job_path, doc, o.output, o.progress_file, threads);
  const JobSpec job = parse_job(doc, job_path.has_parent_path() ? job_path.parent_path() : ".");
  check_memory(job, o.max_memory);

  // 2. Solve, with progress every ~2 s.
  SolveOptions options;
  options.nested_start = o.start == "nested";
  if (!o.vtk_dir.empty()) options.vtk_dir = std::filesystem::path(o.vtk_dir);
  if (!o.checkpoint_file.empty()) options.checkpoint_file = std::filesystem::path(o.checkpoint_file);
  if (!o.resume_file.empty()) options.resume_file = std::filesystem::path(o.resume_file);
  if (!o.bed_cache.empty()) options.bed_cache = std::filesystem::path(o.bed_cache);
  options.stop_requested = [] { return stop_requested(); };
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  std::optional<std::chrono::steady_clock::time_point> previous_iteration;
  IterationTimes times;
  options.on_iteration = [&](const IterationReport& r) {
    const auto now = std::chrono::steady_clock::now();
    if (previous_iteration) {
      times.latest_s = std::chrono::duration<double>(now - *previous_iteration).count();
      times.longest_s = std::max(times.longest_s.value_or(0.0), *times.latest_s);
    }
    previous_iteration = now;
    const bool every = spdlog::should_log(spdlog::level::debug);  // -v: every iteration
    if (!every && r.iteration != 1 && now - last < std::chrono::seconds(2)) return;
    last = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (!o.progress_file.empty()) {
      try {
        write_atomically(o.progress_file, progress_json(r, elapsed, times, job.numerics.cells, threads).dump() + "\n");
      } catch (const std::exception& e) {
        spdlog::warn("progress file: {}", e.what());
      }
    }
    if (every)
      spdlog::debug("iteration {:6d}  continuity {:.2e}  momentum {:.2e}  dp_star {:.8g} (change {:.1e})  "
                    "pressure {} / momentum {} linear iterations  {:.2f} s",
                    r.iteration, r.continuity, r.momentum, r.qoi.value_or(0.0), r.qoi_change,
                    r.pressure_iterations, r.momentum_iterations, elapsed);
    else if (r.qoi)
      spdlog::info("iteration {:6d}  continuity {:.2e}  momentum {:.2e}  dp_star {:.6g} (change {:.1e})  {:.1f} s",
                   r.iteration, r.continuity, r.momentum, *r.qoi, r.qoi_change, elapsed);
    else
      spdlog::info("iteration {:6d}  continuity {:.2e}  momentum {:.2e}  {:.1f} s", r.iteration, r.continuity,
                   r.momentum, elapsed);
  };
  spdlog::info("solving {} on {}x{}x{} cells with {} thread(s)", job.case_spec.name, job.numerics.cells[0],
               job.numerics.cells[1], job.numerics.cells[2], threads);
  install_stop_handlers();
  JobResult result;
  try {
    result = solve_job(job, options);
  } catch (const SolveStopped& stopped) {
    spdlog::warn("{}; {}", stopped.what(),
                 stopped.checkpoint_written ? "checkpoint written to " + o.checkpoint_file : "no checkpoint written");
    return to_int(ExitCode::kInterrupted);
  }
  if (result.status == SolveStatus::kConverged)
    spdlog::info("converged after {} iterations: dp_star = {:.8g} ({:.1f} s)", result.iterations,
                 result.dp_star.value_or(0.0), result.wall_s);
  else
    spdlog::warn("{}: {}", solve_status_name(result.status), result.reason);

  // 3. Write the result.
  const std::string text = to_json(result).dump(2) + "\n";
  if (o.output.empty()) std::cout << text << std::flush;
  else write_atomically(o.output, text);
  return to_int(result.status == SolveStatus::kConverged ? ExitCode::kOk : ExitCode::kNotConverged);
}

}  // namespace

void add_solve_command(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<SolveCommandOptions>();
  auto* sub = app.add_subcommand("solve", "solve one job: steady gas flow through a frozen bed on one grid");
  sub->add_option("job", opts->job_file, "job JSON file")->required();
  sub->add_option("-o,--output", opts->output, "result JSON file (default: stdout)");
  sub->add_option("--threads", opts->threads, "OpenMP threads (default: OMP_NUM_THREADS, else all cores)");
  sub->add_option("--start", opts->start,
                  "nested: from the solution on a grid with half the cells per axis (grids of " +
                      std::to_string(SolveOptions{}.nested_min_cells) +
                      " cells or more); analytic: from the plug-flow warm start only")
      ->check(CLI::IsMember({"nested", "analytic"}))
      ->capture_default_str();
  sub->add_option("--max-memory", opts->max_memory,
                  "refuse jobs whose estimated memory exceeds this (e.g. 8G; default: physical memory)");
  sub->add_option("--vtk", opts->vtk_dir, "write the final fields as legacy VTK into this folder");
  sub->add_option("--progress", opts->progress_file,
                  "rewrite this JSON file (iteration, residuals, elapsed) every ~2 s while solving");
  sub->add_option("--checkpoint", opts->checkpoint_file,
                  "on SIGTERM/SIGINT, write the solver state here (atomically) and exit 130");
  sub->add_option("--resume", opts->resume_file,
                  "continue from this checkpoint if it is this job's (missing: start from zero; "
                  "corrupt or another job's: warning, start from zero)");
  sub->add_option("--bed-cache", opts->bed_cache,
                  "keep generated beds in this folder and reuse them (same generator, case and worker; "
                  "docs/PARTICLES.md \"Bed cache\")");
  sub->add_flag("-v,--verbose", opts->verbose, "debug output");
  sub->add_flag("-q,--quiet", opts->quiet, "warnings and errors only");
  sub->callback([opts, &exit_code] { exit_code = run_solve(*opts); });
}

}  // namespace gridfree::worker_cli
