// SPDX-License-Identifier: GPL-3.0-or-later
// A physical case (docs/INTERFACE.md §2, the "case" object of a job) as typed values:
// domain, particle size, gas, boundaries, where the particles come from, and
// the pressure-drop probes. Parsed by job/job_spec.h (parse_case); kept here,
// in the lowest layer, so particle generators can read it without depending
// on the job module.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

namespace gridfree {

enum class BoundaryKind { kPeriodic, kWall, kMassInflow, kPressureOutflow };

struct BoundarySpec {
  BoundaryKind kind = BoundaryKind::kWall;
  double superficial_velocity_cm_s = 0;  // mass_inflow
  double pressure_dyn_cm2 = 0;           // pressure_outflow
};

struct GasSpec {
  double density_g_cm3 = 1e-3;
  double viscosity_g_cm_s = 2e-4;
};

// particles: exactly one of generator / file / uniform.
struct GeneratorSpec {
  std::string kind;          // "bursting_bubble" | "uniform_random" | "sscp_like"
  nlohmann::json params;     // the whole generator object (kind-specific fields)
  std::string where;         // JSON pointer of the generator object, for messages
};
struct FileSpec {
  std::filesystem::path path;  // resolved against the job/study file's folder
  std::string format;          // "csv" | "mfix" | "lammps"
  // LAMMPS dumps only: the unit system ("si" | "cgs") and the snapshot's timestep.
  std::string units;
  std::optional<std::int64_t> timestep;
};
struct UniformSpec {
  double solids_fraction = 0;
};
using ParticleSource = std::variant<GeneratorSpec, FileSpec, UniformSpec>;

struct ParticleVelocitySpec {
  double thermal_cm_s = 0;  // std of each velocity component; 0 = frozen
  std::uint64_t seed = 0;
};

struct ProbeSpec {
  double y1_dp = 4;
  double y2_dp = 104;
};

struct CaseSpec {
  std::string name;
  std::array<double, 3> domain_dp{};     // L* per direction (particle diameters)
  double particle_diameter_cm = 0;
  GasSpec gas;
  std::array<double, 3> gravity_cm_s2{};
  // boundaries[axis][side]: side 0 = low, 1 = high. Periodic on both sides or neither.
  std::array<std::array<BoundarySpec, 2>, 3> boundaries{};
  ParticleSource particles = UniformSpec{};
  ParticleVelocitySpec particle_velocity;
  ProbeSpec probes;

  std::array<double, 3> domain_cm() const {
    return {domain_dp[0] * particle_diameter_cm, domain_dp[1] * particle_diameter_cm,
            domain_dp[2] * particle_diameter_cm};
  }
  bool periodic(int axis) const { return boundaries[axis][0].kind == BoundaryKind::kPeriodic; }
};

}  // namespace gridfree
