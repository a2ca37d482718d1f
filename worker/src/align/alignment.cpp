// SPDX-License-Identifier: GPL-3.0-or-later
// Grid-alignment check (alignment.h).
#include "align/alignment.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace gridfree {

std::vector<AlignVariant> alignment_variants(const std::array<std::vector<int>, 3>& cell_offsets,
                                             const std::vector<double>& shift_fractions, int shift_axis) {
  auto or_zero = [](const auto& v) { return v.empty() ? std::decay_t<decltype(v)>{0} : v; };
  const auto ox = or_zero(cell_offsets[0]), oy = or_zero(cell_offsets[1]), oz = or_zero(cell_offsets[2]);
  const auto fs = or_zero(shift_fractions);
  std::vector<AlignVariant> out;
  for (int y : oy)
    for (int x : ox)
      for (int z : oz)
        for (double f : fs) out.push_back({{x, y, z}, shift_axis, f});
  return out;
}

ParticleSet shifted_particles(const ParticleSet& set, const Grid& grid, int axis, double fraction) {
  ParticleSet out = set;
  if (fraction == 0) return out;
  const double shift = fraction * grid.h(axis), length = grid.length[axis];
  for (Particle& p : out.particles) {
    double& x = axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
    x += shift;
    if (grid.periodic[axis]) {
      x = std::fmod(x, length);
      if (x < 0) x += length;
    } else if (x < 0 || x > length) {
      throw InputError("--shift-fractions", "shifting by " + std::to_string(fraction) +
                                                " of a cell moves a particle centre out of the domain");
    }
  }
  return out;
}

void summarise_alignment(AlignReport& r) {
  std::vector<double> dp;
  for (const auto& v : r.variants)
    if (v.status == SolveStatus::kConverged && v.dp_star) dp.push_back(*v.dp_star);
  if (dp.size() != r.variants.size() || dp.size() < 2) {
    r.reason = dp.size() < 2 && dp.size() == r.variants.size() ? "fewer than two variants"
                                                                : "not every variant converged with a dp_star";
    return;
  }
  double sum = 0;
  for (double v : dp) sum += v;
  r.mean = sum / double(dp.size());
  r.min = *std::min_element(dp.begin(), dp.end());
  r.max = *std::max_element(dp.begin(), dp.end());
  r.spread = (*r.max - *r.min) / *r.mean;
}

AlignReport run_alignment(const JobSpec& job, const ParticleSet& particles, const std::vector<AlignVariant>& variants,
                          const SolveOptions& options) {
  AlignReport report;
  for (const AlignVariant& v : variants) {
    JobSpec variant_job = job;
    AlignVariantResult out;
    out.variant = v;
    for (int a = 0; a < 3; ++a) {
      out.cells[a] = job.numerics.cells[a] + v.cell_offsets[a];
      if (out.cells[a] < 1) throw InputError("--cells-offsets", "an offset leaves fewer than one cell");
    }
    variant_job.numerics.cells = out.cells;
    const Grid grid = job_grid(job.case_spec, out.cells);
    const JobResult r =
        solve_with_particles(variant_job, shifted_particles(particles, grid, v.shift_axis, v.shift_fraction), options);
    out.delta_star = r.delta_star;
    out.status = r.status;
    out.reason = r.reason;
    out.dp_star = r.dp_star;
    out.iterations = r.iterations;
    report.variants.push_back(out);
  }
  summarise_alignment(report);
  return report;
}

}  // namespace gridfree
