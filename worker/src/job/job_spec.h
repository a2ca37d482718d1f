// SPDX-License-Identifier: GPL-3.0-or-later
// A worker job (docs/INTERFACE.md §2, schemas/job.schema.json) as typed values.
//
// parse_job() validates a JSON document against the embedded schema and the
// semantic rules (probes inside the domain, positive sizes, known names, ...)
// and throws InputError naming every offending JSON path. The case types
// (CaseSpec, BoundarySpec, ParticleSource, ...) live in core/case_spec.h.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "core/case_spec.h"
#include "core/input_error.h"
#include "deposition/filter.h"
#include "deposition/transfer_stencils.h"
#include "drag/drag_law.h"
#include "schemes/limiter.h"

namespace gridfree {

enum class DepositionKind { kDiffusion, kCentroid };

// numerics.deposition (docs/TRANSFER.md): how particle data reach the grid
// and grid data reach the particles. The defaults are the measured default
// transfer; the presets of job/deposition_parse.h expand to explicit values.
struct DepositionSpec {
  DepositionKind kind = DepositionKind::kDiffusion;
  double fwhm_dp = 6;
  FilterDiffusivity diffusivity = FilterDiffusivity::kConsistent;
  PreDeposition pre_deposition = PreDeposition::kTrilinear;
  Sampling sampling = Sampling::kTrilinear;
  FilterIntegration integration = FilterIntegration::kExact;
  int steps = 8;                   // integration = steps only
  double truncation_sigmas = 4;    // pre_deposition = gaussian only
};

struct TolerancesSpec {
  double linear = 1e-2;   // loosest relative residual of an inner solve (docs/SOLVER.md)
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
  int stall_window = 0;  // outer iterations without halving the residual before a stop; 0 = off
  // What a first stall does (docs/SOLVER.md "Stalled outer iterations"):
  // end the job (false, the default), or relax the deferred correction and
  // give it one more window ("relax_correction").
  bool relax_stalled_correction = false;
};

struct JobSpec {
  CaseSpec case_spec;
  NumericsSpec numerics;
  nlohmann::json source;  // the job document as given (for hashing / provenance)
};

// Parses a case object (shared by jobs and studies). `path` is the JSON
// pointer of the object ("/case" in a job, "/cases/PC1" in a study);
// `base_dir` resolves relative particle file paths. Checks the semantic rules
// (probes inside the domain, particle file exists, generator parameters fit
// the domain, ...) and adds every problem found to `problems`; does not throw
// for user errors. Schema validation is the caller's job (parse_job does it).
CaseSpec parse_case(const nlohmann::json& j, const std::string& path,
                    const std::filesystem::path& base_dir, ProblemList& problems);

// Parses a numerics object; `domain_dp` turns grid.delta_star into cells.
NumericsSpec parse_numerics(const nlohmann::json& j, const std::string& path,
                            const std::array<double, 3>& domain_dp, ProblemList& problems);

// Validates (schema, then semantics) and parses a whole job document.
// Throws InputError listing every problem.
JobSpec parse_job(const nlohmann::json& doc, const std::filesystem::path& base_dir);

// read_json_file + parse_job with base_dir = the file's folder.
JobSpec parse_job_file(const std::filesystem::path& file);

// Reads a JSON file; malformed JSON throws InputError "file:line:col".
nlohmann::json read_json_file(const std::filesystem::path& file);

// Name <-> enum of the deposition settings ("diffusion", "seed", ...).
std::string_view deposition_kind_name(DepositionKind kind);
std::string_view filter_diffusivity_name(FilterDiffusivity d);

// numerics.deposition (job/deposition_parse.cpp): presets expanded, defaults
// filled in, contradictory combinations reported with their JSON pointer.
DepositionSpec parse_deposition(const nlohmann::json& dep, const std::string& path, ProblemList& problems);
// The explicit (expanded) JSON of a deposition: what a job records and hashes.
nlohmann::json deposition_json(const DepositionSpec& dep, const nlohmann::json& given);

}  // namespace gridfree
