// SPDX-License-Identifier: GPL-3.0-or-later
// Every (study, grid) pair is an independent problem: they run concurrently
// on the OpenMP threads, largest grids first (they dominate the time), each
// problem on one thread (the solvers' own parallel loops are nested and so
// inactive). The studies are assembled afterwards in the fixed order, so the
// output does not depend on the thread count.
#include "verify/verify.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <string>

#include "verify/filter_order.h"
#include "verify/manufactured_flow.h"

namespace gridfree {
namespace {

struct Task {
  std::size_t study = 0;
  std::size_t grid = 0;
  int n = 0;
};

}  // namespace

std::vector<OrderStudy> run_code_verification(const VerifyOptions& options) {
  std::vector<Limiter> schemes = options.schemes;
  if (schemes.empty())
    for (const auto& info : limiters()) schemes.push_back(info.limiter);
  const std::vector<int> grids = !options.grids.empty() ? options.grids
                                 : options.quick        ? std::vector<int>{16, 32, 64}
                                                        : std::vector<int>{16, 32, 64, 128};

  // One solver per study: the flow study of each scheme, then the filter.
  std::vector<OrderStudy> studies;
  std::vector<std::function<GridOutcome(int)>> solve;
  for (Limiter scheme : schemes) {
    studies.push_back(manufactured_flow_study(scheme));
    solve.push_back([scheme](int n) { return manufactured_flow_outcome(scheme, n); });
  }
  studies.push_back(filter_order_study());
  solve.push_back(filter_outcome);

  std::vector<Task> tasks;
  for (std::size_t s = 0; s < studies.size(); ++s)
    for (std::size_t k = 0; k < grids.size(); ++k) tasks.push_back({s, k, grids[k]});
  std::stable_sort(tasks.begin(), tasks.end(), [](const Task& a, const Task& b) { return a.n > b.n; });
  std::vector<std::vector<GridOutcome>> outcomes(studies.size(), std::vector<GridOutcome>(grids.size()));
  const long count = static_cast<long>(tasks.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long t = 0; t < count; ++t) {
    const Task& task = tasks[std::size_t(t)];
    GridOutcome& out = outcomes[task.study][task.grid];
    try {  // an exception must not leave the parallel region
      out = solve[task.study](task.n);
    } catch (const std::exception& e) {
      out.failure = std::string("grid ") + std::to_string(task.n) + ": " + e.what();
    }
  }

  for (std::size_t s = 0; s < studies.size(); ++s) {
    finish_study(studies[s], grids, outcomes[s]);
    if (options.on_study) options.on_study(studies[s]);
  }
  return studies;
}

}  // namespace gridfree
