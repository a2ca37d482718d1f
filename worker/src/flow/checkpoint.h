// SPDX-License-Identifier: GPL-3.0-or-later
// Checkpoints of a solve that was asked to stop (docs/INTERFACE.md §2,
// "Checkpoints"): the iterated fields (p, u, β, βv̄) and the loop counters,
// so that a resumed solve continues with the next outer iteration exactly as
// the uninterrupted one would have.
//
// File layout (host byte order; a checkpoint is read back on the machine
// family that wrote it):
//   "GFCKPT01"                      8 bytes, magic and format version
//   header length L                 8 bytes, uint64
//   header                          L bytes, JSON: job_hash, cells, iteration,
//                                   qoi_history, first_continuity,
//                                   first_momentum, arrays [{name, size}]
//   arrays                          the doubles of each array, in that order
//   SHA-256                         64 hex characters of everything above
// Written to a temporary file in the same folder and renamed, so a reader
// sees the old checkpoint or the new one, never half of one. A checkpoint
// whose magic, checksum, job hash, grid or array sizes do not match is
// refused (read_checkpoint says why); it is never partly used.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <variant>

#include "flow/flow_state.h"
#include "flow/simple_loop.h"

namespace gridfree {

struct Checkpoint {
  std::string job_hash;
  std::array<int, 3> cells{};
  LoopCounters counters;
  FlowState state;  // p, u, drag.beta, drag.beta_v (the rest is derived)
};

// Writes atomically (temporary file + rename). Throws std::runtime_error on
// an I/O failure.
void write_checkpoint(const std::filesystem::path& file, const std::string& job_hash, const Grid& grid,
                      const FlowState& state, const LoopCounters& counters);

// The checkpoint for this job and grid, or the reason it cannot be used
// (missing file, wrong magic, checksum, job hash, grid or array size).
std::variant<Checkpoint, std::string> read_checkpoint(const std::filesystem::path& file,
                                                      const std::string& job_hash, const Grid& grid);

}  // namespace gridfree
