// SPDX-License-Identifier: GPL-3.0-or-later
// A grid-convergence study (docs/INTERFACE.md §3): cases × factor levels × grids.
//
// parse_study() reads and validates a study file (schema + semantics, every
// problem with its JSON pointer); expand() turns it into series and jobs.
// A series is one case at one set of factor levels over all grids, for one
// quantity: a physical case's factors are convection, fwhm_dp, drag and
// deposition (its quantity dp*); an external case's are the study's own
// (template placeholders, `levels`), one series per declared quantity. A job
// is one configuration on one grid: the full job document of
// docs/INTERFACE.md §2 and its job_hash.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/job_spec.h"
#include "study/adaptive_grids.h"
#include "study/external_case.h"
#include "study/external_ladder.h"
#include "study/study_ensembles.h"

namespace gridfree {

// The factor levels of one series.
struct SeriesKey {
  std::string case_name;
  std::string convection = "superbee";
  double fwhm_dp = 6;
  std::string drag = "bvk";
  std::string deposition = "diffusion";  // "diffusion" | "centroid" | a preset "fm18" | "mfix" | a transfer level's name
  std::string quantity{};                // an external case's quantity (study/external_case.h); "" for dp*
  // An external case's factor levels: the study's factor name → the level's
  // text as rendered into the template (empty without factors).
  std::map<std::string, std::string> levels{};

  auto operator<=>(const SeriesKey&) const = default;
  // "PC1 superbee fwhm6 bvk" (+ " centroid"); external: "cavity kinetic_energy",
  // with levels "cavity scheme=QUICK kinetic_energy".
  std::string label() const;
  bool external() const { return !quantity.empty(); }
};

// Factor levels as one canonical JSON text: {"name":"level",...}, keys in
// byte order, no spaces ("{}" without factors): the series' `levels`
// column (docs/DATABASE.md).
std::string levels_json(const std::map<std::string, std::string>& levels);
// The inverse; an empty map for "" or text that is not such an object.
std::map<std::string, std::string> levels_from_json(const std::string& text);

// The expanded transfer of a series (study_transfer.h): series table columns.
struct TransferColumns {
  std::string pre_deposition, sampling, integration, diffusivity;  // "" = does not apply
  int steps = 0;                                                   // integration "steps" only
  bool operator==(const TransferColumns&) const = default;
};

struct StudyFactors {
  std::vector<std::string> convection, drag, deposition;
  std::vector<double> fwhm_dp;
  // An external study's factors (study/external_factors.h): placeholder
  // name → its levels as text, in the order given.
  std::map<std::string, std::vector<std::string>> external;
};

struct StudyCase {
  std::string name;
  nlohmann::json doc;  // the case object, "name" set, particle file path made absolute
  CaseSpec spec;                        // physical cases
  std::optional<ExternalCase> external;  // external cases (then spec is unused)
};

struct ExtrapolationSettings {
  std::string weights = "inverse_h";
  double p_low = 0.5, p_high = 2.1;
  std::string method = "averaged";  // averaged | capped | fm | eh14
  std::optional<double> expected_order;  // formal order of the discretization (extrap/bias_checks.h)
};

// The alignment check of a study (study_alignment.h): which grids are
// re-solved with which cell-count offsets.
struct AlignmentOption {
  std::vector<std::size_t> grids;            // indices into the study's grid list
  std::array<std::vector<int>, 3> offsets;   // nx, ny, nz offsets ({0} when not given)
};

// Longest study name: it names the report folder and the database row, and
// file systems stop at 255 bytes per folder name (docs/LIMITS.md).
inline constexpr std::size_t kMaxStudyNameLength = 100;
// Longest description: free text kept with the definition (docs/LIMITS.md).
inline constexpr std::size_t kMaxStudyDescriptionLength = 10000;

struct Study {
  std::string name;
  nlohmann::json definition;        // the study document as read
  std::filesystem::path base_dir;   // folder of the study file
  std::vector<StudyCase> cases;     // in file order
  StudyFactors factors;             // levels as given (missing factor = its default)
  std::map<std::string, nlohmann::json> transfer_levels;  // object deposition levels by name (study_transfer.h)
  std::map<std::string, std::size_t> deposition_level_index;  // a level's index in the file's factors.deposition
  std::optional<SeriesKey> baseline;  // set for one_at_a_time designs (an external one: case and levels)
  std::vector<double> grid_delta_star;            // grids: {"delta_star": [...]}
  std::vector<std::array<int, 3>> grid_cells;     // or grids: {"cells": [...]}
  std::optional<AdaptiveGrids> adaptive_grids;    // or grids as a target (grid_delta_star = its ladder)
  GridVariables grid_variables;                   // or grids: {"variables": {...}} (external cases)
  std::map<std::string, ExternalLadder> external_ladders;  // or an external adaptive ladder, per case
  nlohmann::json numerics = nlohmann::json::object();  // merged into every job
  ExtrapolationSettings extrapolation;
  std::optional<AlignmentOption> alignment;  // off unless the study asks
  Ensembles ensembles;              // name → instance cases (study_ensembles.h)

  const StudyCase* find_case(const std::string& name) const;
  bool external() const { return !cases.empty() && cases.front().external.has_value(); }
  std::string design_description() const;  // "factorial" or "one_at_a_time (baseline ...)"
};

// An external case's grid variables: its adaptive ladder's rungs
// (study/external_ladder.h), or the study's grids.variables.
const GridVariables& external_grids_of(const Study& study, const std::string& case_name);

struct StudyJob {
  std::size_t series = 0;          // index into ExpandedStudy::series
  std::size_t grid = 0;            // index of the grid in the study's list
  std::array<int, 3> cells{};
  double delta_star = 0;           // (V/N)^(1/3)/d of this grid, actual; an external case's h
  std::optional<double> delta_star_nominal;  // as requested in grids.delta_star (none for cells)
  nlohmann::json doc;              // the job document
  std::string hash;                // job_hash(doc)
};

// A re-aligned variant of a series' grid (not part of its extrapolation).
struct AlignmentJob {
  std::size_t series = 0, grid = 0;
  std::array<int, 3> offsets{}, cells{};
  double delta_star = 0;
  nlohmann::json doc;
  std::string hash, base_hash;     // this job, and the grid's own job
};

struct ExpandedStudy {
  std::vector<SeriesKey> series;
  std::vector<TransferColumns> transfer;  // per series, its expanded transfer
  std::vector<StudyJob> jobs;      // series-major, grids in the study's order
  std::vector<AlignmentJob> alignment;  // empty unless the study has "alignment"
};

// Reads, validates and parses a study file. Throws InputError with every
// problem found (JSON pointer + reason).
Study parse_study(const std::filesystem::path& file);

// Validates and parses an already-read document (base_dir resolves relative
// particle files). Throws InputError.
Study parse_study_document(const nlohmann::json& doc, const std::filesystem::path& base_dir);

// An external study's configurations (case and levels, no quantity) in
// design order: one job per configuration and grid.
std::vector<SeriesKey> external_configurations(const Study& study);

// The series of the design, without duplicates, baseline first.
std::vector<SeriesKey> design_series(const Study& study);

// Cells of every grid of the study for one case.
std::vector<std::array<int, 3>> grids_for_case(const Study& study, const StudyCase& c);

// Builds one job document (docs/INTERFACE.md §2) for a series on a grid.
nlohmann::json make_job_document(const Study& study, const SeriesKey& key,
                                 const std::array<int, 3>& cells);

// Series and jobs of the study, hashed.
ExpandedStudy expand(const Study& study);

// The study's distinct jobs (an external case's job is in each of its
// quantities' series, so `jobs` lists it once per quantity).
std::size_t distinct_job_count(const ExpandedStudy& expanded);

// Δ* = (L*x L*y L*z / N)^(1/3) for a domain in particle diameters.
double delta_star_of(const std::array<double, 3>& domain_dp, const std::array<int, 3>& cells);

}  // namespace gridfree
