// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker align JOB.json [--cells-y-offsets 0,1,...] [--cells-x-offsets ...]
//     [--cells-z-offsets ...] [--shift-fractions 0,0.25,...] [--shift-axis x|y|z]
//     [-o OUT.json] [--threads N] [-q]
//
// Re-solves the job's grid for every combination of the cell-count offsets
// and particle shifts (align/alignment.h, docs/TRANSFER.md) and writes JSON:
//   {"job_hash", "variants": [{"cells", "cell_offsets", "shift_axis",
//    "shift_fraction", "delta_star", "status", "reason", "dp_star",
//    "iterations"}...], "dp_star_mean", "dp_star_min", "dp_star_max",
//    "spread", "reason"}
// spread = (max − min)/mean over the variants, null (with the reason) unless
// every variant converged. Exit 0 when it has a spread, 3 when not, 2 for
// invalid input (fewer than two variants, offsets leaving no cell, a shift
// that moves particles out of a non-periodic domain).
#include <omp.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include <spdlog/spdlog.h>

#include "align/alignment.h"
#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "job/job_hash.h"
#include "job/job_spec.h"
#include "particles/particle_io.h"

namespace gridfree::worker_cli {
namespace {

struct AlignOptions {
  std::string job_file, output, shift_axis = "y";
  std::array<std::vector<int>, 3> offsets;
  std::vector<double> fractions;
  int threads = 0;
  bool quiet = false;
};

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

int run_align(const AlignOptions& o) {
  spdlog::set_level(o.quiet ? spdlog::level::warn : spdlog::level::info);
  if (o.threads < 0) throw InputError("--threads", "must be a positive number of threads");
  omp_set_num_threads(o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  const int axis = o.shift_axis == "x" ? 0 : (o.shift_axis == "y" ? 1 : (o.shift_axis == "z" ? 2 : -1));
  if (axis < 0) throw InputError("--shift-axis", "must be x, y or z");
  const std::vector<AlignVariant> variants = alignment_variants(o.offsets, o.fractions, axis);
  if (variants.size() < 2) throw InputError("--cells-y-offsets", "give at least two variants (offsets or shifts)");

  const std::filesystem::path job_path(o.job_file);
  const nlohmann::json doc = read_json_file(job_path);
  const JobSpec job = parse_job(doc, job_path.has_parent_path() ? job_path.parent_path() : ".");
  const ParticleSet particles = load_particles(job.case_spec.particles, job.case_spec);
  SolveOptions options;
  options.on_iteration = [](const IterationReport&) {};
  spdlog::set_level(spdlog::level::warn);  // per-variant progress only
  AlignReport report;
  for (const AlignVariant& v : variants) {
    const AlignReport one = run_alignment(job, particles, {v}, options);
    const AlignVariantResult& r = one.variants.front();
    if (!o.quiet)
      std::cerr << "cells " << r.cells[0] << "x" << r.cells[1] << "x" << r.cells[2] << " shift " << r.variant.shift_fraction
                << ": " << solve_status_name(r.status) << " dp_star " << r.dp_star.value_or(NAN) << "\n";
    report.variants.push_back(r);
  }
  summarise_alignment(report);

  nlohmann::json out{{"job_hash", job_hash(job.source)}, {"variants", nlohmann::json::array()}};
  for (const auto& r : report.variants)
    out["variants"].push_back({{"cells", r.cells},
                               {"cell_offsets", r.variant.cell_offsets},
                               {"shift_axis", std::string(1, "xyz"[r.variant.shift_axis])},
                               {"shift_fraction", r.variant.shift_fraction},
                               {"delta_star", r.delta_star},
                               {"status", std::string(solve_status_name(r.status))},
                               {"reason", r.reason},
                               {"dp_star", optional_json(r.dp_star)},
                               {"iterations", r.iterations}});
  out["dp_star_mean"] = optional_json(report.mean);
  out["dp_star_min"] = optional_json(report.min);
  out["dp_star_max"] = optional_json(report.max);
  out["spread"] = optional_json(report.spread);
  out["reason"] = report.reason;
  const std::string text = out.dump(2) + "\n";
  if (o.output.empty()) std::cout << text;
  else std::ofstream(o.output) << text;
  return to_int(report.spread ? ExitCode::kOk : ExitCode::kNotConverged);
}

}  // namespace

void add_align_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<AlignOptions>();
  auto* sub = app.add_subcommand("align", "grid-alignment check: dp* over cell-count offsets and particle shifts");
  sub->add_option("job", o->job_file, "job JSON file")->required();
  sub->add_option("--cells-x-offsets", o->offsets[0], "offsets added to n_x (comma-separated)")->delimiter(',');
  sub->add_option("--cells-y-offsets", o->offsets[1], "offsets added to n_y (comma-separated)")->delimiter(',');
  sub->add_option("--cells-z-offsets", o->offsets[2], "offsets added to n_z (comma-separated)")->delimiter(',');
  sub->add_option("--shift-fractions", o->fractions, "particle shifts in cells (comma-separated)")->delimiter(',');
  sub->add_option("--shift-axis", o->shift_axis, "axis of the particle shift: x, y or z (default y)");
  sub->add_option("-o,--output", o->output, "output JSON file (default: stdout)");
  sub->add_option("--threads", o->threads, "OpenMP threads (default: all cores)");
  sub->add_flag("-q,--quiet", o->quiet, "no per-variant progress");
  sub->callback([o, &exit_code] { exit_code = run_align(*o); });
}

}  // namespace gridfree::worker_cli
