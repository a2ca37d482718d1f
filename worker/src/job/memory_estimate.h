// SPDX-License-Identifier: GPL-3.0-or-later
// The worker's own memory guard: an estimate of a job's peak memory from its
// cell count, checked against a limit before anything is allocated, so that
// no job allocates its way into the kernel's OOM killer.
//
//   memory(N) = kWorkerBytesPerCell · N + kWorkerBaseBytes
//
// The orchestrator's plan and scheduler use the same model. Measured
// 2026-11-29 on the bursting-bubble baseline (docs/BENCHMARKS.md, "Memory
// per cell"): peak RSS 337 B/cell at 480 k cells and 319 B/cell at
// 3.84 M, the heap at its peak 321 B/cell at 60 k (bench/memory_account.sh).
// 400 B/cell leaves ≈ 25 % over the 3.84 M figure for what the baseline
// does not have (moving particles add βv̄: 24 B/cell), plus 64 MiB for the
// executable, particles and buffers.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gridfree {

inline constexpr double kWorkerBytesPerCell = 400.0;
inline constexpr double kWorkerBaseBytes = 64.0 * 1024 * 1024;

double job_memory_estimate_bytes(const std::array<int, 3>& cells);

// Physical memory of this machine (sysconf), 0 when unknown.
std::uint64_t machine_memory_bytes();

// "8G", "512M", "64k", "1.5G", "2000000000" (bytes; K/M/G/T are powers of
// 1024, an optional trailing "B" or "iB" is accepted); nullopt otherwise.
std::optional<double> parse_memory_size(std::string_view text);

// "1.2 GiB", "850 MiB".
std::string memory_text(double bytes);

}  // namespace gridfree
