// SPDX-License-Identifier: GPL-3.0-or-later
// Checkpoint files (flow/checkpoint.h).
#include "flow/checkpoint.h"

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "flow/checkpoint_fields.h"
#include "job/job_hash.h"

namespace gridfree {
namespace {

constexpr char kMagic[9] = "GFCKPT01";
constexpr std::size_t kDigest = 64;

void append_bytes(std::string& out, const void* data, std::size_t n) {
  out.append(static_cast<const char*>(data), n);
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const std::string& job_hash, const Grid& grid,
                      const FlowState& state, const LoopCounters& counters) {
  const auto arrays = checkpoint_arrays(state);
  nlohmann::json header = {{"job_hash", job_hash},
                           {"cells", grid.n},
                           {"iteration", counters.iteration},
                           {"qoi_history", counters.qoi_history},
                           {"first_continuity", counters.first_continuity},
                           {"first_momentum", counters.first_momentum},
                           {"arrays", nlohmann::json::array()}};
  for (const auto& a : arrays) header["arrays"].push_back({{"name", a.name}, {"size", a.values.size()}});
  const std::string text = header.dump();
  std::string bytes(kMagic, 8);
  const std::uint64_t length = text.size();
  append_bytes(bytes, &length, sizeof length);
  bytes += text;
  for (const auto& a : arrays) append_bytes(bytes, a.values.data(), a.values.size() * sizeof(double));
  bytes += sha256_hex(bytes);

  const std::filesystem::path tmp = file.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write checkpoint " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

std::variant<Checkpoint, std::string> read_checkpoint(const std::filesystem::path& file, const std::string& job_hash,
                                                      const Grid& grid) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::string("cannot read it");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 16 + kDigest || bytes.compare(0, 8, kMagic) != 0) return std::string("not a gridfree checkpoint");
  const std::size_t body = bytes.size() - kDigest;
  if (sha256_hex(std::string_view(bytes).substr(0, body)) != bytes.substr(body))
    return std::string("checksum mismatch (truncated or corrupt)");
  std::uint64_t length = 0;
  std::memcpy(&length, bytes.data() + 8, sizeof length);
  if (length > body - 16) return std::string("header length out of range");
  Checkpoint cp;
  std::vector<CheckpointArray> arrays;
  std::size_t at = 16 + length;
  try {
    const auto h = nlohmann::json::parse(bytes.substr(16, length));
    cp.job_hash = h.at("job_hash").get<std::string>();
    cp.cells = h.at("cells").get<std::array<int, 3>>();
    cp.counters.iteration = h.at("iteration").get<int>();
    cp.counters.qoi_history = h.at("qoi_history").get<std::vector<double>>();
    cp.counters.first_continuity = h.at("first_continuity").get<double>();
    cp.counters.first_momentum = h.at("first_momentum").get<double>();
    for (const auto& a : h.at("arrays")) {
      const auto n = a.at("size").get<std::size_t>();
      if (n > (body - at) / sizeof(double)) return std::string("array sizes exceed the file");
      CheckpointArray arr{a.at("name").get<std::string>(), std::vector<double>(n)};
      if (n > 0) std::memcpy(arr.values.data(), bytes.data() + at, n * sizeof(double));  // empty: data() may be null
      at += n * sizeof(double);
      arrays.push_back(std::move(arr));
    }
  } catch (const nlohmann::json::exception& e) {
    return std::string("bad header: ") + e.what();
  }
  if (at != body) return std::string("trailing bytes after the arrays");
  if (cp.job_hash != job_hash) return "it belongs to job " + cp.job_hash.substr(0, 12) + ", not " + job_hash.substr(0, 12);
  if (cp.cells != grid.n)
    return "its grid " + std::to_string(cp.cells[0]) + "x" + std::to_string(cp.cells[1]) + "x" +
           std::to_string(cp.cells[2]) + " is not the job's";
  if (cp.counters.iteration < 1) return std::string("iteration counter < 1");
  std::string why;
  if (!checkpoint_sizes_match(grid, arrays, why)) return why;
  restore_checkpoint_arrays(grid, std::move(arrays), cp.state);
  return cp;
}

}  // namespace gridfree
