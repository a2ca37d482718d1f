// SPDX-License-Identifier: GPL-3.0-or-later
// A case's particles from its source (generator, file or uniform bed).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <type_traits>

#include "particles/particle_io.h"

namespace gridfree {
namespace {

LammpsOptions lammps_options(const FileSpec& s) {
  if (s.units != "si" && s.units != "cgs")
    throw InputError(s.path.string(), "a lammps dump needs units si or cgs, got '" + s.units + "'");
  return {s.units == "si" ? 100.0 : 1.0, s.timestep};
}

// A file that states its box must match the case's domain: a different
// periodic length would change the physics silently.
void check_box(const ParticleSet& set, const std::array<double, 3>& domain_cm) {
  if (!set.box_cm) return;
  for (int a = 0; a < 3; ++a) {
    const double box = (*set.box_cm)[std::size_t(a)], domain = domain_cm[std::size_t(a)];
    if (std::abs(box - domain) > 1e-6 * domain) {
      char buf[256];
      std::snprintf(buf, sizeof buf, "the box is %.9g cm along %c but the case's domain is %.9g cm (domain_dp x diameter)",
                    box, "xyz"[a], domain);
      throw InputError(set.source, buf);
    }
  }
}

}  // namespace

GeneratedParticles load_particles_with_report(const ParticleSource& source, const CaseSpec& case_spec,
                                              const BedGenerator& generate) {
  GeneratedParticles out;
  const auto L = case_spec.domain_cm();
  const double volume = L[0] * L[1] * L[2];
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, GeneratorSpec>) {
          out = generate ? generate(s, case_spec) : generate_particles_with_report(s, case_spec);
        } else if constexpr (std::is_same_v<T, FileSpec>) {
          if (s.format == "csv") out.set = read_csv(s.path);
          else if (s.format == "mfix") out.set = read_mfix(s.path);
          else if (s.format == "lammps") out.set = read_lammps_dump(s.path, lammps_options(s));
          else throw InputError(s.path.string(), "unknown particle file format '" + s.format + "' (csv, mfix or lammps)");
          check_box(out.set, L);
          check_particles(out.set, case_spec);
          double solids = 0;
          for (const Particle& p : out.set.particles) solids += std::numbers::pi * p.d * p.d * p.d / 6.0;
          RegionReport r{"domain", volume, 0.0, out.set.particles.size(), volume > 0 ? solids / volume : 0.0};
          r.target_fraction = r.solids_fraction;  // a file has no target: report what it holds
          out.regions.push_back(r);
        } else {
          out.regions.push_back({"domain (continuum)", volume, s.solids_fraction, 0, s.solids_fraction});
        }
      },
      source);
  apply_thermal_velocity(out.set, case_spec.particle_velocity);
  return out;
}

ParticleSet load_particles(const ParticleSource& source, const CaseSpec& case_spec, const BedGenerator& generate) {
  return load_particles_with_report(source, case_spec, generate).set;
}

}  // namespace gridfree
