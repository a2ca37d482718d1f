// SPDX-License-Identifier: GPL-3.0-or-later
// The kind of a study's cases (docs/DESIGN.md "The case-kind interface"):
// what differs between gridfree's own particle bed (study/particle_bed_kind.cpp)
// and a user's code run from a template (study/external_kind.cpp), chosen
// once from the study, a series key or a job document. Callers in store/,
// sched/ and the plan ask the kind instead of which kind it is; a new kind
// of case is one more implementation and one more line in case_kind.cpp.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/adaptive_grids.h"
#include "study/adaptive_rungs.h"
#include "study/case_vocabulary.h"
#include "study/cost_model.h"
#include "study/external_cost.h"
#include "study/study.h"
#include "study/study_plan.h"

namespace gridfree {

// An adaptive series' ladder: each rung with the job document that runs it
// and that job's actual h (Δ* for a particle bed).
struct KindLadder {
  std::vector<AdaptiveRung> rungs;
  std::vector<nlohmann::json> specs;
  std::vector<double> h;
  // The rungs' cost is gridfree's model, to be scaled by the series'
  // measured/model ratio; false: the rungs carry the kind's own estimate.
  bool scale_by_measured = true;
};

class CaseKind {
 public:
  virtual ~CaseKind() = default;

  // "particle_bed", "external".
  virtual std::string name() const = 0;

  // Which words the reports use for it (study/case_vocabulary.h).
  virtual CaseKindId id() const = 0;
  // Its words without a case's declared meanings: the cell-size symbol.
  CaseVocabulary vocabulary() const { return case_vocabulary(id()); }

  // A running job's log label from its series' label (`k.label()`, with
  // " alignment" for an alignment variant), its document and cells.
  virtual std::string job_label(const std::string& series_label, const nlohmann::json& spec,
                                const std::array<int, 3>& cells) const = 0;

  // The job's name in a queue listing (Slurm --job-name): two jobs of one
  // study on one grid get different names.
  virtual std::string job_name(const std::string& study_name, const std::string& label, double delta_star,
                               const nlohmann::json& spec) const = 0;

  // One job serves several series (an external case's quantities): jobs are
  // counted by their hash, not by the (series, grid) pairs of the expansion.
  virtual bool job_serves_several_series() const = 0;

  // A job's document depends on files outside the study definition (a
  // template's text, a code version): the stored jobs are compared with the
  // expansion on every submit, and a reused job takes the new document.
  virtual bool jobs_follow_outside_files() const = 0;

  // The series table's particle-bed columns (convection, fwhm_dp, drag,
  // deposition) apply; NULL otherwise (docs/DATABASE.md).
  virtual bool has_bed_columns() const = 0;

  // Completes a finished job's result before it is stored: the result
  // document (`result_json`) and its cells (`result_cells`, all zero when
  // the code did not report them) from the job's document and cells.
  virtual void take_result(const nlohmann::json& spec, const std::array<int, 3>& job_cells, std::string& result_json,
                           std::array<int, 3>& result_cells) const = 0;

  // The job's CPU and memory estimate when gridfree's cost model
  // (study/cost_model.h) does not describe it: from the study's declared
  // figures (`declared`, by case name) and the measured `history` (by
  // cost_similarity_key), NaN where unknown. nullopt: gridfree's model applies.
  virtual std::optional<ExternalJobCost> own_cost(const nlohmann::json& spec, const std::array<int, 3>& cells,
                                                  const std::map<std::string, DeclaredCost>& declared,
                                                  const CostHistory& history) const = 0;

  // A job's cores are tasks of an MPI run (an external template's
  // `mpirun -np @@cores@@`: Slurm --ntasks), not threads of one process
  // (the worker's --threads: --cpus-per-task).
  virtual bool cores_are_tasks() const = 0;

  // gridfree reads the job's values from its run folder (an external case's
  // collect section), so a finished job is read again, not rerun, when the
  // study's way of reading changes (sched/recollect.h).
  virtual bool results_recollectable() const = 0;

  // The plan (`gridfree validate --plan`, study/study_plan.h).
  virtual Plan plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                    const CostHistory& history) const = 0;

  // The adaptive ladder of series `key` whose first job is `first_spec`;
  // `measured`: the series' finished jobs (cells, CPU s) under
  // cost_similarity_key(first_spec).
  virtual KindLadder adaptive_ladder(const nlohmann::json& definition, const AdaptiveGrids& settings,
                                     const SeriesKey& key, const nlohmann::json& first_spec,
                                     const CostHistory& measured) const = 0;
};

const CaseKind& particle_bed_kind();
const CaseKind& external_kind();

// The kind of a series, of a study (its cases are all of one kind), of a job document.
const CaseKind& case_kind(const SeriesKey& key);
const CaseKind& case_kind(const Study& study);
const CaseKind& case_kind_of_job(const nlohmann::json& spec);
// The kind of a stored study definition (its "cases"; none: a particle bed).
const CaseKind& case_kind_of_definition(const nlohmann::json& definition);

}  // namespace gridfree
