// A worker job (CONTRACT.md §2, schemas/job.schema.json) as typed values.
//
// parse_job() validates a JSON document against the embedded schema and the
// semantic rules (probes inside the domain, positive sizes, known names, ...)
// and throws InputError naming every offending JSON path.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "deposition/filter.h"
#include "drag/drag_law.h"
#include "core/input_error.h"
#include "schemes/limiter.h"

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
};
struct FileSpec {
  std::filesystem::path path;  // resolved against the job/study file's folder
  std::string format;          // "csv" | "mfix"
};
struct UniformSpec {
  double solids_fraction = 0;
};
using ParticleSource = std::variant<GeneratorSpec, FileSpec, UniformSpec>;

struct ParticleVelocitySpec {
  double thermal_cm_s = 0;  // std of each velocity component; 0 = frozen
  unsigned seed = 0;
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
};

enum class DepositionKind { kDiffusion, kCentroid };

struct DepositionSpec {
  DepositionKind kind = DepositionKind::kDiffusion;
  double fwhm_dp = 6;
  FilterDiffusivity diffusivity = FilterDiffusivity::kSeed;
};

struct TolerancesSpec {
  double linear = 1e-8;
  double filter = 1e-10;
  double steady = 1e-5;
};

struct NumericsSpec {
  std::array<int, 3> cells{};  // from grid.cells, or from grid.delta_star
  Limiter convection = Limiter::kSuperbee;
  DragLaw drag = DragLaw::kBvk;
  DepositionSpec deposition;
  TolerancesSpec tolerances;
  int max_iterations = 20000;
};

struct JobSpec {
  CaseSpec case_spec;
  NumericsSpec numerics;
  nlohmann::json source;  // the job document as given (for hashing / provenance)
};

// Parses a case object (shared by jobs and studies). `path` is the JSON
// pointer of the object ("/case" in a job, "/cases/PC1" in a study);
// `base_dir` resolves relative particle file paths.
CaseSpec parse_case(const nlohmann::json& j, const std::string& path,
                    const std::filesystem::path& base_dir, ProblemList& problems);

// Validates and parses a whole job document. Throws InputError.
JobSpec parse_job(const nlohmann::json& doc, const std::filesystem::path& base_dir);

// Reads a JSON file; malformed JSON throws InputError with line and column.
nlohmann::json read_json_file(const std::filesystem::path& file);

}  // namespace gridfree
