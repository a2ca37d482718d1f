// A case's particles from its source (generator, file or uniform bed).
#include <cmath>
#include <numbers>
#include <type_traits>

#include "particles/particle_io.h"

namespace gridfree {

GeneratedParticles load_particles_with_report(const ParticleSource& source, const CaseSpec& case_spec) {
  GeneratedParticles out;
  const auto L = case_spec.domain_cm();
  const double volume = L[0] * L[1] * L[2];
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, GeneratorSpec>) {
          out = generate_particles_with_report(s, case_spec);
        } else if constexpr (std::is_same_v<T, FileSpec>) {
          if (s.format == "csv") out.set = read_csv(s.path);
          else if (s.format == "mfix") out.set = read_mfix(s.path);
          else throw InputError(s.path.string(), "unknown particle file format '" + s.format + "' (csv or mfix)");
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

ParticleSet load_particles(const ParticleSource& source, const CaseSpec& case_spec) {
  return load_particles_with_report(source, case_spec).set;
}

}  // namespace gridfree
