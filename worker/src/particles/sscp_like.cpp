// SPDX-License-Identifier: GPL-3.0-or-later
// A bubbling-bed-like snapshot (the SSCP-I-like case, PHYSICS.md §6): a
// packed emulsion at ε_s ≈ 0.55–0.6 with a few bubbles at ε_s ≈ 0.01.
// Random sequential addition jams near 0.38, so the emulsion is built as
// follows (docs/PARTICLES.md has the reasoning):
//
// 1. Bubbles: `bubbles` spheres of radius R, centres uniform in the bed
//    (y* < bed_height) and at least R from walls, not overlapping each other.
//
// emulsion "random" (the default):
// 2. N_e = round(φ · V_emulsion / V_p) centres packed by overlap removal
//    with growing diameters (particles/dense_packing.h), centres in the bed
//    and outside the bubbles.
//
// emulsion "lattice" (kept to show how cells alias a crystal's layers):
// 2. Lattice: an FCC lattice with nearest-neighbour spacing
//    s = d (0.7405/φ_L)^(1/3), φ_L a little above the target. On each axis
//    the sites sit on layers at spacing h ≥ s/√2 — stretched to fit the
//    centre interval [r, L − r] of a wall axis, or an even number of layers
//    over L on a periodic axis — and site (i,j,k) is used when i+j+k is even.
//    Neighbours are then at least s apart. Sites whose centre lies in a
//    bubble are dropped.
// 3. Vacancies: N_e = round(φ · V_emulsion / V_p) sites are kept, chosen by
//    a seeded partial Fisher–Yates shuffle (V_emulsion = V_bed − ΣV_bubble).
// 4. Jitter: each particle moves by a random vector of length
//    < (s − d)/2, which cannot create an overlap.
// 5. Relaxation: `relaxation_sweeps` sweeps of hard-sphere Monte Carlo
//    (random trial moves, rejected on overlap, on leaving the bed, or on
//    entering a bubble). At ε_s ≈ 0.58 the crystal does not melt: the
//    emulsion keeps FCC layers about 0.75 d apart on every axis.
// 6. Bubble particles: round(ε_b · V_bubble / V_p) per bubble by random
//    sequential addition inside each sphere.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "particles/compression_packing.h"
#include "particles/dense_packing.h"
#include "particles/generator_params.h"
#include "particles/sphere_packer.h"

namespace gridfree {
namespace {

constexpr double kFccDensest = 0.74048;  // π/(3√2), FCC packing fraction at s = d

// Layer positions of one axis: the centre interval is [lo, hi] (a wall or
// bed-top axis) or [0, L) (periodic); spacing at least h_min.
std::vector<double> layers(double lo, double hi, bool periodic, double h_min) {
  std::vector<double> out;
  if (periodic) {
    int n = static_cast<int>(std::floor(hi / h_min));
    n -= n % 2;  // even, so the i+j+k parity is consistent across the wrap
    for (int i = 0; i < n; ++i) out.push_back(hi * i / n);
    return out;
  }
  const double span = hi - lo;
  if (span < 0) return out;
  const int n = static_cast<int>(std::floor(span / h_min)) + 1;
  if (n == 1) {
    out.push_back(0.5 * (lo + hi));
    return out;
  }
  for (int i = 0; i < n; ++i) out.push_back(lo + span * i / (n - 1));
  return out;
}

struct Lattice {
  std::vector<Vec3> sites;  // outside every bubble
  double spacing = 0;       // guaranteed minimum distance between sites
};

// Steps 2–5 of the lattice emulsion (header comment).
void place_lattice_emulsion(const SscpLikeParams& p, SpherePacker& packer, ParticleRandom& rng,
                            const std::vector<Vec3>& bubbles, double radius, double bed_top, std::size_t n_emulsion,
                            const std::string& where) {
  const double d = packer.diameter(), r = 0.5 * d;
  // Centres allowed for emulsion particles: the packer's bounds, y <= bed_top − r.
  const auto in_bed = [&](const Vec3& x) { return packer.within_bounds(x) && x[1] <= bed_top - r; };
  const auto in_a_bubble = [&](const Vec3& x) {
    return std::any_of(bubbles.begin(), bubbles.end(), [&](const Vec3& b) {
      return packer.cells().distance_squared(x, b) < radius * radius;
    });
  };
  // 2. The loosest lattice (φ_L from target + 0.05 upwards) with enough sites.
  Lattice lattice;
  for (double phi_lattice = std::min(p.solids_fraction + 0.05, 0.70);; phi_lattice += 0.005) {
    if (phi_lattice > kFccDensest - 0.005)
      throw InputError(where + "/solids_fraction", "the lattice cannot hold this many particles in this bed");
    const double s = d * std::cbrt(kFccDensest / phi_lattice);
    const double h_min = s / std::numbers::sqrt2;
    std::array<std::vector<double>, 3> axis;
    for (int a = 0; a < 3; ++a) {
      const double hi = a == 1 ? bed_top - r : packer.hi(a);
      axis[a] = layers(packer.lo(a), hi, packer.periodic(a) && a != 1, h_min);
    }
    lattice.sites.clear();
    lattice.spacing = s;
    for (std::size_t k = 0; k < axis[2].size(); ++k)
      for (std::size_t j = 0; j < axis[1].size(); ++j)
        for (std::size_t i = 0; i < axis[0].size(); ++i) {
          if ((i + j + k) % 2 != 0) continue;
          const Vec3 x{axis[0][i], axis[1][j], axis[2][k]};
          if (!in_a_bubble(x)) lattice.sites.push_back(x);
        }
    if (lattice.sites.size() >= n_emulsion) break;
  }

  // 3. Vacancies: keep a random n_emulsion of the sites, in lattice order.
  std::vector<std::size_t> order(lattice.sites.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (std::size_t i = 0; i < n_emulsion; ++i) std::swap(order[i], order[i + rng.below(order.size() - i)]);
  order.resize(n_emulsion);
  std::sort(order.begin(), order.end());

  // 4. Jitter within (s − d)/2 (a cube of half-width 0.49 (s − d)/√3 keeps a margin).
  const double jitter = 0.49 * (lattice.spacing - d) / std::sqrt(3.0);
  for (std::size_t i : order) {
    const Vec3& site = lattice.sites[i];
    Vec3 x{site[0] + jitter * (2 * rng.uniform() - 1), site[1] + jitter * (2 * rng.uniform() - 1),
           site[2] + jitter * (2 * rng.uniform() - 1)};
    x = packer.wrap(x);
    if (!in_bed(x) || in_a_bubble(x)) x = site;
    packer.add(x);
  }

  // 5. Hard-sphere Monte Carlo; the step adapts (deterministically) towards
  //    an acceptance ratio of 0.3–0.5.
  double step = 0.1 * d;
  for (int sweep = 0; sweep < p.relaxation_sweeps; ++sweep) {
    std::size_t accepted = 0;
    for (std::uint32_t id = 0; id < n_emulsion; ++id) {
      const Vec3 from = packer.centres()[id];
      const Vec3 to = packer.wrap({from[0] + step * (2 * rng.uniform() - 1), from[1] + step * (2 * rng.uniform() - 1),
                                   from[2] + step * (2 * rng.uniform() - 1)});
      if (in_bed(to) && !in_a_bubble(to) && packer.fits(to, id)) {
        packer.move(id, to);
        ++accepted;
      }
    }
    const double ratio = n_emulsion > 0 ? static_cast<double>(accepted) / static_cast<double>(n_emulsion) : 0.5;
    if (ratio < 0.3) step = std::max(0.8 * step, 0.005 * d);
    else if (ratio > 0.5) step = std::min(1.25 * step, 0.5 * d);
  }

}

}  // namespace

GeneratedParticles generate_sscp_like(const SscpLikeParams& p, const CaseSpec& c, const std::string& where) {
  const double d = c.particle_diameter_cm, r = 0.5 * d;
  const Vec3 L = c.domain_cm();
  const double vp = particle_volume(d);
  const double bed_top = p.bed_height_dp * d;
  const double radius = p.bubble_radius_dp * d;
  SpherePacker packer(L, periodic_axes(c), d);
  ParticleRandom rng(p.seed);

  // 1. Bubbles.
  std::vector<Vec3> bubbles;
  for (int attempt = 0; static_cast<int>(bubbles.size()) < p.bubbles; ++attempt) {
    if (attempt > 100000) throw InputError(where + "/bubbles", "could not fit that many non-overlapping bubbles in the bed");
    Vec3 b{};
    for (int a = 0; a < 3; ++a) {
      const double top = a == 1 ? bed_top : L[a];
      b[a] = packer.periodic(a) ? rng.uniform(0, L[a]) : rng.uniform(radius, top - radius);
    }
    const bool apart = std::none_of(bubbles.begin(), bubbles.end(), [&](const Vec3& o) {
      return packer.cells().distance_squared(b, o) < 4 * radius * radius;
    });
    if (apart) bubbles.push_back(b);
  }
  const double v_bubble = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double v_bubbles = v_bubble * static_cast<double>(bubbles.size());
  const double v_emulsion = L[0] * bed_top * L[2] - v_bubbles;
  const auto n_emulsion = static_cast<std::size_t>(std::llround(p.solids_fraction * v_emulsion / vp));

  if (p.emulsion == SscpEmulsion::kLattice) {
    place_lattice_emulsion(p, packer, rng, bubbles, radius, bed_top, n_emulsion, where);
  } else {
    DensePackingRegion region;
    region.length = L;
    for (int a = 0; a < 3; ++a) {
      region.periodic[a] = packer.periodic(a);
      region.lo[a] = packer.lo(a);
      region.hi[a] = a == 1 ? bed_top - r : packer.hi(a);
    }
    region.holes = bubbles;
    region.hole_radius = radius;
    try {
      const std::vector<Vec3> centres = p.emulsion == SscpEmulsion::kCompression
                                            ? compressed_dense_packing(region, d, n_emulsion, rng)
                                            : random_dense_packing(region, d, n_emulsion, rng);
      for (const Vec3& x : centres) packer.add(x);
    } catch (const std::runtime_error& e) {
      throw InputError(where + "/solids_fraction", std::string("the random packing did not converge: ") + e.what());
    }
  }

  // 6. The dilute bubbles.
  const auto n_per_bubble = static_cast<std::size_t>(std::llround(p.bubble_solids_fraction * v_bubble / vp));
  std::size_t n_bubble_particles = 0;
  for (const Vec3& b : bubbles) {
    const Box cube{{b[0] - radius, b[1] - radius, b[2] - radius}, {b[0] + radius, b[1] + radius, b[2] + radius}};
    const std::size_t placed = packer.add_random(n_per_bubble, rng, cube, [&](const Vec3& x) {
      return packer.cells().distance_squared(x, b) < radius * radius;
    });
    if (placed < n_per_bubble)
      throw InputError(where + "/bubble_solids_fraction", "could not place the bubble particles");
    n_bubble_particles += placed;
  }

  GeneratedParticles out;
  out.set.particles.reserve(packer.centres().size());
  for (const Vec3& x : packer.centres()) out.set.particles.push_back({x[0], x[1], x[2], d, 0, 0, 0});
  out.regions.push_back(make_report("emulsion", v_emulsion, p.solids_fraction, n_emulsion, d));
  if (!bubbles.empty())
    out.regions.push_back(make_report("bubbles", v_bubbles, p.bubble_solids_fraction, n_bubble_particles, d));
  out.regions.push_back(make_report("freeboard", L[0] * (L[1] - bed_top) * L[2], 0.0, 0, d));
  return out;
}

}  // namespace gridfree
