// SPDX-License-Identifier: GPL-3.0-or-later
// The bed summary of a job's result (see bed_summary.h).
#include "particles/bed_summary.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gridfree {
namespace {

constexpr double kProfileMarginDp = 2.0;  // slabs this far inside the bed's extent count for the ε_s(y) range

// A number, or null when it is not finite (e.g. g(r) of a bed without a core).
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json peak_json(const StructurePeak& p) {
  return {{"axis", std::string(1, "xyz"[p.axis])}, {"period_dp", num(p.period_dp)}, {"s_over_n", num(p.s_over_n)}};
}

}  // namespace

nlohmann::json bed_summary(const BedStructure& s, const std::vector<Particle>& particles,
                           const std::array<double, 3>& length_cm) {
  nlohmann::json j;
  j["particles"] = s.particles;
  if (particles.empty() || !(s.diameter_cm > 0)) return j;
  const double d = s.diameter_cm;
  double bottom = particles[0].y - 0.5 * particles[0].d, top = particles[0].y + 0.5 * particles[0].d, solid = 0;
  for (const Particle& p : particles) {
    bottom = std::min(bottom, p.y - 0.5 * p.d);
    top = std::max(top, p.y + 0.5 * p.d);
    solid += std::numbers::pi * p.d * p.d * p.d / 6;
  }
  top = std::min(top, length_cm[1]);
  j["height_dp"] = num(top / d);
  j["solids_fraction"] = num(top > 0 ? solid / (length_cm[0] * length_cm[2] * top) : 0.0);
  j["largest_structure_factor"] = peak_json(s.largest_peak);
  j["largest_structure_factor_core"] = peak_json(s.largest_core_peak);
  j["core_particles"] = s.core_particles;
  j["ordered"] = s.largest_core_peak.s_over_n >= kOrderedPeak;
  j["rdf"] = {{"contact_peak", num(s.rdf.contact_peak)},
              {"contact_peak_r_dp", num(s.rdf.contact_peak_r_dp)},
              {"at_sqrt3_dp", num(s.rdf.at_sqrt3)},
              {"at_2_dp", num(s.rdf.at_2)},
              {"reference_particles", s.rdf.reference_particles}};
  // ε_s(y) over the slabs [b d, (b + 1) d) inside the bed's extent less the margins.
  const double lo = bottom + kProfileMarginDp * d, hi = top - kProfileMarginDp * d;
  double min = 0, max = 0;
  int first = -1, last = -1;
  for (std::size_t b = 0; b < s.solids_fraction_y.size(); ++b) {
    const double y0 = static_cast<double>(b) * d, y1 = y0 + d;
    if (y0 < lo - 1e-9 * d || y1 > hi + 1e-9 * d) continue;
    const double v = s.solids_fraction_y[b];
    if (first < 0) min = max = v, first = static_cast<int>(b);
    min = std::min(min, v);
    max = std::max(max, v);
    last = static_cast<int>(b);
  }
  if (first >= 0)
    j["solids_fraction_y"] = {{"min", num(min)}, {"max", num(max)}, {"from_dp", first}, {"to_dp", last + 1}};
  j["local_solids_fraction"] = {{"cube_dp", s.local_cube_dp}, {"mean", num(s.local_mean)}, {"std", num(s.local_std)}};
  return j;
}

}  // namespace gridfree
