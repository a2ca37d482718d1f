// SPDX-License-Identifier: GPL-3.0-or-later
// The grid of a case: the domain L = L* d (cm) cut into `cells`, periodic
// where the case's boundaries are.
#pragma once

#include <array>

#include "core/case_spec.h"
#include "grid/grid.h"

namespace gridfree {

Grid make_grid(const CaseSpec& case_spec, const std::array<int, 3>& cells);

}  // namespace gridfree
