// SPDX-License-Identifier: GPL-3.0-or-later
// Code verification by the method of manufactured solutions: what
// `gridfree-worker verify` runs (docs/INTERFACE.md §2).
//
//   momentum_continuity_drag  the steady Model A equations with a prescribed
//                             ε_g and β field in a periodic box, one study per
//                             convection scheme (manufactured_flow.h);
//   diffusion_filter          the Gaussian filter on a smooth periodic field
//                             (filter_order.h).
#pragma once

#include <functional>
#include <vector>

#include "schemes/limiter.h"
#include "verify/order_study.h"

namespace gridfree {

struct VerifyOptions {
  bool quick = false;                  // fewer, coarser grids
  std::vector<int> grids;              // cells per direction, coarse to fine; empty: the default set
  std::vector<Limiter> schemes;        // empty = every scheme
  std::function<void(const OrderStudy&)> on_study;  // progress
};

std::vector<OrderStudy> run_code_verification(const VerifyOptions& options);

}  // namespace gridfree
