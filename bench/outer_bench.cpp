// SPDX-License-Identifier: GPL-3.0-or-later
// Outer-iteration variants of one job, for choosing by measurement
// (docs/DESIGN.md, "Outer convergence"): the start (nested or analytic),
// Anderson acceleration depth, Newton–Krylov (GMRES restart length), the
// two-grid FAS (fine sweeps per cycle, coarse sweeps per cycle) and α_u.
// Prints one line per run. "sweeps" are the fine grid's SIMPLEC sweeps (G
// evaluations, flow/simplec_sweep.h) whatever the method; the coarse
// levels of the nested start use the same method.
//
//   outer_bench JOB.json [--start nested|analytic] [--anderson M] [--newton-krylov M]
//               [--fas NU] [--fas-coarse K] [--relax-u A] [--threads N]
#include <omp.h>

#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "flow/solve.h"
#include "job/job_spec.h"

int main(int argc, char** argv) {
  using namespace gridfree;
  CLI::App app{"outer_bench: outer-iteration variants of one job"};
  std::string job_file, start = "nested";
  int anderson = 0, newton_krylov = 0, fas = 0, fas_coarse = 10, threads = 1;
  double relax_u = SimpleSettings{}.relax_u;
  app.add_option("job", job_file, "job JSON")->required();
  app.add_option("--start", start, "nested | analytic")->check(CLI::IsMember({"nested", "analytic"}));
  app.add_option("--anderson", anderson, "Anderson depth (0 = off)")->check(CLI::NonNegativeNumber);
  app.add_option("--newton-krylov", newton_krylov, "GMRES restart length of Newton-Krylov (0 = off)")
      ->check(CLI::NonNegativeNumber);
  bool drag_in_map = false;
  app.add_flag("--nk-drag-in-map", drag_in_map, "Newton-Krylov: update the drag in every G evaluation");
  app.add_option("--fas", fas, "two-grid FAS: fine SIMPLEC sweeps per cycle (0 = off)")->check(CLI::NonNegativeNumber);
  app.add_option("--fas-coarse", fas_coarse, "two-grid FAS: coarse sweeps per cycle")->check(CLI::PositiveNumber);
  app.add_option("--relax-u", relax_u, "momentum under-relaxation")->check(CLI::Range(0.05, 0.99));
  app.add_option("--threads", threads, "OpenMP threads")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  omp_set_num_threads(threads);

  const JobSpec job = parse_job_file(job_file);
  SolveOptions options;
  options.nested_start = start == "nested";
  options.simple.anderson_depth = anderson;
  options.simple.newton_krylov_restart = newton_krylov;
  options.simple.newton_krylov_drag_in_map = drag_in_map;
  options.simple.fas_smoothing_sweeps = fas;
  options.simple.fas_coarse_sweeps = fas_coarse;
  options.simple.relax_u = relax_u;
  const JobResult r = solve_job(job, options);
  std::string coarse = "";
  if (r.extra.contains("nested_start"))
    for (const auto& level : r.extra["nested_start"])
      coarse += (coarse.empty() ? "" : "+") + std::to_string(level["iterations"].get<int>());
  std::string newton = "";
  if (r.extra.contains("newton_krylov"))
    newton = ", " + std::to_string(r.extra["newton_krylov"]["steps"].get<int>()) + " Newton steps (" +
             std::to_string(r.extra["newton_krylov"]["fallbacks"].get<int>()) + " fallbacks)";
  if (r.extra.contains("fas"))
    newton += ", " + std::to_string(r.extra["fas"]["cycles"].get<int>()) + " FAS cycles with " +
              std::to_string(r.extra["fas"]["coarse_sweeps"].get<int>()) + " coarse sweeps";
  std::printf("%s start=%s anderson=%d newton_krylov=%d%s fas=%d/%d relax_u=%.2f: %s, %d sweeps (coarse %s)%s, "
              "dp_star %.10g, wall %.1f s, cpu %.1f s, rss %.1f MB\n",
              job_file.c_str(), start.c_str(), anderson, newton_krylov, drag_in_map ? "+drag" : "", fas, fas_coarse, relax_u,
              std::string(solve_status_name(r.status)).c_str(), r.iterations, coarse.empty() ? "-" : coarse.c_str(),
              newton.c_str(), r.dp_star.value_or(0.0), r.wall_s, r.cpu_s, r.peak_rss_mb);
  return r.status == SolveStatus::kConverged ? 0 : 3;
}
