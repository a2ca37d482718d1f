// SPDX-License-Identifier: GPL-3.0-or-later
// Particle files, their checks, and loading a case's particles.
//
// CSV: a header naming the columns x,y,z,d (cm) and optionally u,v,w
// (cm/s), in any order; a headerless file has 4 or 7 columns in that order.
// Blank lines and lines starting with '#' are skipped. Written with %.17g,
// so a write/read round trip reproduces every double exactly.
//
// MFiX particle_input.dat (cm, g/cm³):
//   - version 1 (MFiX 2016-era decks): headerless lines
//     "x y z radius density [u v w]", blanks or commas between numbers;
//   - version 2.0 (newer releases): first line "Version 2.0", a 34-line
//     header ("Dimension:", "Particles:", and per variable "Name: T|F
//     [default]" for Coordinates, Phase_ID, Diameter, Density, Velocity, ...),
//     data from line 35: x y z [phase] [diameter] [density] [u v w] [...].
//     Only 3-D files are accepted; columns after the velocity are ignored.
// LAMMPS / LIGGGHTS text dump (`dump custom`): the snapshot at a chosen
// timestep (default: the last in the file); columns by the ATOMS header
// (x y z | xu yu zu | xs ys zs, radius | diameter, optional vx vy vz);
// positions relative to the box's low corner; lengths converted to cm.
// Every error names "file:line".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "core/case_spec.h"
#include "particles/generators.h"
#include "particles/particle.h"

namespace gridfree {

void write_csv(const std::filesystem::path& path, const ParticleSet& set);
ParticleSet read_csv(const std::filesystem::path& path);

ParticleSet read_mfix(const std::filesystem::path& path);
// Version-1 format, 8 columns (velocities zero when the set has none).
void write_mfix(const std::filesystem::path& path, const ParticleSet& set, double density_g_cm3 = 1.0);

struct LammpsOptions {
  double length_unit_cm = 1;            // 100 for LAMMPS `units si`, 1 for `units cgs`
  std::optional<std::int64_t> timestep; // the snapshot to read; the last one when unset
};
ParticleSet read_lammps_dump(const std::filesystem::path& path, const LammpsOptions& options);

struct ParticleCheckOptions {
  // Allowed overlap as a fraction of the contact distance r_i + r_j:
  // snapshots of soft-sphere DEM runs carry small overlaps.
  double overlap_tolerance = 0.02;
  std::size_t max_problems = 20;  // listed individually; the rest are counted
};

// Throws InputError when a centre lies outside the domain or two particles
// overlap (minimum image on periodic axes; cell list, O(N)); each problem is
// named "file:line" when the set came from a file, else "particle[i]".
void check_particles(const ParticleSet& set, const CaseSpec& case_spec, const ParticleCheckOptions& options = {});

// The case's particles: generated, read (format "csv" | "mfix" | "lammps") and
// checked, or none for a uniform (continuum) bed; then the case's thermal
// velocities when thermal_cm_s > 0. `generate` makes a generated bed
// (default: generate_particles_with_report).
ParticleSet load_particles(const ParticleSource& source, const CaseSpec& case_spec,
                           const BedGenerator& generate = {});
// The same, with per-region counts and solids fractions (for reports).
GeneratedParticles load_particles_with_report(const ParticleSource& source, const CaseSpec& case_spec,
                                              const BedGenerator& generate = {});

}  // namespace gridfree
