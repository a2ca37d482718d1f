// Time left in a study from the plan's cost model (study/study_plan.h)
// scaled by the times measured so far:
//
//   s     = Σ_done wall_i / Σ_done model_i          (1 when nothing is done yet)
//   left  = Σ_queued s·model_j + Σ_running max(0, s·model_k − elapsed_k)
//   ETA   = left / max(1, workers)
//
// model_i is the cost model's estimate of job i (one thread); s absorbs the
// machine, the threads and the load. Pure functions, no I/O.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct EtaJob {
  double model_s = 0;               // cost-model estimate
  enum class State { kQueued, kRunning, kDone } state = State::kQueued;
  double wall_s = 0;                // measured (done)
  double elapsed_s = 0;             // so far (running)
};

struct Eta {
  double scale = 1;                 // s above
  double seconds_left = 0;          // before dividing by the workers
  double eta_s = 0;                 // left / workers
};

Eta estimate_eta(const std::vector<EtaJob>& jobs, int workers);

// "2 h 05 min", "7 min", "< 1 min".
std::string hours_minutes(double seconds);

}  // namespace gridfree
