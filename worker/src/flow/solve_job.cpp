// SPDX-License-Identifier: GPL-3.0-or-later
// solve_job: load the case's particles, summarise their structure, solve,
// and stamp identity and version.
#include <time.h>

#include <spdlog/spdlog.h>

#include "core/version.h"
#include "flow/solve.h"
#include "job/bed_cache.h"
#include "job/job_hash.h"
#include "particles/bed_summary.h"
#include "particles/particle_io.h"

namespace gridfree {
namespace {

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The result's "bed" (particles/bed_summary.h), with the CPU seconds it
// took; null for a continuum (uniform) bed or one without particles.
nlohmann::json bed_of(const ParticleSet& particles, const CaseSpec& c) {
  if (particles.particles.empty()) return nullptr;
  const double cpu0 = process_cpu_seconds();
  const BedStructure s = bed_structure(particles.particles, c.domain_cm(), {c.periodic(0), c.periodic(1), c.periodic(2)});
  nlohmann::json bed = bed_summary(s, particles.particles, c.domain_cm());
  bed["cpu_s"] = process_cpu_seconds() - cpu0;
  return bed;
}

}  // namespace

JobResult solve_job(const JobSpec& job, const SolveOptions& options) {
  const ParticleSet particles = load_particles(job.case_spec.particles, job.case_spec,
                                               options.bed_cache ? cached_bed_generator(*options.bed_cache) : BedGenerator{});
  spdlog::debug("{} particles", particles.particles.size());
  nlohmann::json bed = bed_of(particles, job.case_spec);
  JobResult result = solve_with_particles(job, particles, options);
  result.bed = std::move(bed);
  result.job_hash = job_hash(job.source);
  result.version = version_string();
  return result;
}

}  // namespace gridfree
