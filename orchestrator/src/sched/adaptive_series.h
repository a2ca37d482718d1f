// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive series in the store (docs/ORCHESTRATOR.md "Adaptive series"):
// after each finished job, before ready series are extrapolated, every
// adaptive series of the study whose jobs have all finished gets one
// decision (sched/adaptive_decision.h) on its results so far:
//
//   continue  → the next rung's job is added to the series (queued, or
//               reused when the store has it done already) — the series is
//               no longer ready;
//   stop      → series.adaptive_status = target_met | target_not_reached,
//               adaptive_note = the sentence; the series is then finished
//               like any other (finish_ready_series).
//
// Each decision, its new job link and its event (kind 'adaptive') are one
// transaction, made only if the series still has exactly the links and no
// unfinished job it was decided on: a killed run resumes with the same
// decisions (they depend on the stored results only) and no duplicates.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sched/adaptive_decision.h"
#include "store/store.h"

namespace gridfree {

// The fit summary an adaptive decision reads, from the extrapolation JSON
// (docs/INTERFACE.md §4) of `ng` converged grids.
AdaptiveFit adaptive_fit_of(const nlohmann::json& extrapolation, int ng);

// Decides every adaptive series of the study that is ready; returns the
// number of decisions written.
int advance_adaptive_series(Store& store, long long study_id);

struct AdaptiveEvent {
  std::string at, message;
};

// The study's adaptive decisions in order (events of kind 'adaptive').
std::vector<AdaptiveEvent> adaptive_events(Store& store, long long study_id);

}  // namespace gridfree
