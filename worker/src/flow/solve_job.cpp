// solve_job: load the case's particles, solve, and stamp identity and version.
#include <spdlog/spdlog.h>

#include "core/version.h"
#include "flow/solve.h"
#include "job/job_hash.h"
#include "particles/particle_io.h"

namespace gridfree {

JobResult solve_job(const JobSpec& job, const SolveOptions& options) {
  const ParticleSet particles = load_particles(job.case_spec.particles, job.case_spec);
  spdlog::debug("{} particles", particles.particles.size());
  JobResult result = solve_with_particles(job, particles, options);
  result.job_hash = job_hash(job.source);
  result.version = version_string();
  return result;
}

}  // namespace gridfree
