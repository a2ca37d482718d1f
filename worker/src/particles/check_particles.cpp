// SPDX-License-Identifier: GPL-3.0-or-later
// Sanity checks of a loaded configuration against its case: every centre in
// the domain, no two particles overlapping beyond a tolerance (minimum image
// on periodic axes, cell list with bins ≥ the largest diameter). Time is
// bounded by the message cap: the check ends once it has that many problems.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "particles/cell_list.h"
#include "particles/particle_io.h"

namespace gridfree {
namespace {

std::string name_of(const ParticleSet& set, std::size_t i) {
  if (!set.source.empty() && i < set.source_lines.size()) return set.source + ":" + std::to_string(set.source_lines[i]);
  return "particle[" + std::to_string(i) + "]";
}

}  // namespace

void check_particles(const ParticleSet& set, const CaseSpec& case_spec, const ParticleCheckOptions& options) {
  const Vec3 L = case_spec.domain_cm();
  std::vector<Problem> problems;
  std::size_t extra = 0;
  const auto add = [&](std::string where, std::string reason) {
    if (problems.size() < options.max_problems) problems.push_back({std::move(where), std::move(reason)});
    else ++extra;
  };

  static const char* const kAxis[3] = {"x", "y", "z"};
  double d_max = 0;
  for (std::size_t i = 0; i < set.particles.size(); ++i) {
    const Particle& p = set.particles[i];
    const double c[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      if (c[a] < 0 || c[a] > L[a]) {
        std::ostringstream os;
        os << "centre " << kAxis[a] << " = " << c[a] << " cm lies outside the domain [0, " << L[a] << "]";
        add(name_of(set, i), os.str());
        break;
      }
    }
    if (!(p.d > 0)) add(name_of(set, i), "the diameter must be > 0");
    d_max = std::max(d_max, p.d);
  }

  if (d_max > 0 && problems.empty()) {
    CellList cells(L, {case_spec.periodic(0), case_spec.periodic(1), case_spec.periodic(2)}, d_max);
    // Stops at the message cap: n coincident particles would otherwise cost
    // n²/2 distance tests (13 s for 5 000) only to be counted.
    for (std::size_t i = 0; i < set.particles.size() && problems.size() < options.max_problems; ++i) {
      const Particle& p = set.particles[i];
      const Vec3 c{p.x, p.y, p.z};
      cells.for_each_near(c, [&](std::uint32_t j) {
        const Particle& q = set.particles[j];
        const double contact = 0.5 * (p.d + q.d);
        const double distance = std::sqrt(cells.distance_squared(c, {q.x, q.y, q.z}));
        if (distance < contact * (1 - options.overlap_tolerance)) {
          std::ostringstream os;
          os << "overlaps " << name_of(set, j) << " (centres " << distance << " cm apart, contact at " << contact
             << " cm)";
          add(name_of(set, i), os.str());
        }
      });
      cells.insert(static_cast<std::uint32_t>(i), c);
    }
  }
  if (extra > 0) problems.push_back({"", "... and " + std::to_string(extra) + " more problems"});
  else if (problems.size() >= options.max_problems && options.max_problems > 0)
    problems.push_back({"", "... the check stops after " + std::to_string(options.max_problems) + " problems"});
  if (!problems.empty()) throw InputError(std::move(problems));
}

}  // namespace gridfree
