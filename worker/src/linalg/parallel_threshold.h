// SPDX-License-Identifier: GPL-3.0-or-later
// One threshold for every OpenMP loop over cells or vector entries: below
// it a loop runs on one thread, since starting the team costs more than the
// loop saves.
#pragma once

#include <cstddef>

namespace gridfree {

inline constexpr std::size_t kParallelCells = 20000;

}  // namespace gridfree
