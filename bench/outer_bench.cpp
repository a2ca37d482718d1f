// Outer-iteration variants of one job, for choosing by measurement
// (docs/DESIGN.md, "Outer convergence"): the start (nested or analytic),
// Anderson acceleration depth and α_u. Prints one line per run.
//
//   outer_bench JOB.json [--start nested|analytic] [--anderson M] [--relax-u A] [--threads N]
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
  int anderson = 0, threads = 1;
  double relax_u = SimpleSettings{}.relax_u;
  app.add_option("job", job_file, "job JSON")->required();
  app.add_option("--start", start, "nested | analytic")->check(CLI::IsMember({"nested", "analytic"}));
  app.add_option("--anderson", anderson, "Anderson depth (0 = off)")->check(CLI::NonNegativeNumber);
  app.add_option("--relax-u", relax_u, "momentum under-relaxation")->check(CLI::Range(0.05, 0.99));
  app.add_option("--threads", threads, "OpenMP threads")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  omp_set_num_threads(threads);

  const JobSpec job = parse_job_file(job_file);
  SolveOptions options;
  options.nested_start = start == "nested";
  options.simple.anderson_depth = anderson;
  options.simple.relax_u = relax_u;
  const JobResult r = solve_job(job, options);
  int coarse_iterations = 0;
  if (r.extra.contains("nested_start"))
    for (const auto& level : r.extra["nested_start"]) coarse_iterations += level["iterations"].get<int>();
  std::printf("%s start=%s anderson=%d relax_u=%.2f: %s, %d iterations (+%d coarse), dp_star %.10g, wall %.1f s, cpu %.1f s, rss %.1f MB\n",
              job_file.c_str(), start.c_str(), anderson, relax_u, std::string(solve_status_name(r.status)).c_str(), r.iterations,
              coarse_iterations, r.dp_star.value_or(0.0), r.wall_s, r.cpu_s, r.peak_rss_mb);
  return r.status == SolveStatus::kConverged ? 0 : 3;
}
