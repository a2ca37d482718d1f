// SPDX-License-Identifier: GPL-3.0-or-later
// The stopping rule of an adaptive series (docs/EXTRAPOLATION.md "Adaptive
// series"), a pure function of the series so far. After every finished rung
// of the ladder (study/adaptive_grids.h), in this order:
//
//   1. target met:  ng ≥ 4 converged grids, verdict `converged`, and the
//      finest converged grid's RDE ≤ target_rde            → stop (target_met)
//   2. ladder end:  no rung left above finest_delta_star   → stop (target_not_reached)
//   3. cap:         the next rung's estimated memory > max_memory (default the
//      machine's), or its predicted CPU s·model > max_cpu_s → stop (target_not_reached)
//   4. otherwise the next rung of the ladder                → continue
//
// The fit read here is the window's when the coarse grids were left out
// (sched/adaptive_window.h); the message then says which grids were used.
//
// The next grid is always the next rung (no skipping: every rung keeps the
// ratio of neighbouring grids the study asked for). The cost of a rung is
// the cost model's one-thread CPU time (study/study_plan.h) times the series'
// measured scale s = Σ cpu_s / Σ model over its finished jobs (1 when none
// has a time); "saved" is that cost summed over the rungs not run.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "study/adaptive_rungs.h"

namespace gridfree {

// What the series' extrapolation says (from the extrapolation JSON).
struct AdaptiveFit {
  int ng = 0;                     // converged grids
  std::string verdict;            // converged | pre-asymptotic | unreliable | insufficient_grids | "" (none)
  std::optional<double> finest_delta_star, finest_rde, f0, finest_u;
  // Non-empty when the fit is a window of the finest grids
  // (sched/adaptive_window.h): window_sentence(), appended to every message.
  std::string window;
};

struct AdaptiveDecision {
  enum class Kind { kContinue, kTargetMet, kTargetNotReached } kind = Kind::kContinue;
  std::size_t next_rung = 0;      // kContinue: index of the rung to run
  double saved_cpu_s = 0;         // estimated CPU seconds of the rungs not run
  std::size_t rungs_not_run = 0;
  std::string message;            // the sentence for the events table and the report
};

// `rungs_started`: rungs 0 .. rungs_started-1 have been run (finished);
// `cost_scale`: s above; `machine_memory_bytes`: the default memory cap.
AdaptiveDecision decide_adaptive_step(const AdaptiveGrids& settings, const std::vector<AdaptiveRung>& ladder,
                                      std::size_t rungs_started, const AdaptiveFit& fit, double cost_scale,
                                      double machine_memory_bytes);

// "adaptive_status" word of the series after a decision (schema step 5).
std::string adaptive_status_word(AdaptiveDecision::Kind kind);

}  // namespace gridfree
