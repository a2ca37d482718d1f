// SPDX-License-Identifier: GPL-3.0-or-later
// Checkpoint files (flow/checkpoint.h): a round trip restores every value
// bit for bit; a checkpoint of another job or grid, a truncated or altered
// file, or a missing one is refused with its reason.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <variant>

#include "flow/checkpoint.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

Grid small_grid() {
  Grid g;
  g.n = {3, 4, 2};
  g.length = {1.0, 2.0, 0.5};
  g.periodic = {true, false, true};
  return g;
}

// A state with distinct, non-round values everywhere (so a swapped or
// shifted array cannot pass).
FlowState sample_state(const Grid& g) {
  FlowState s;
  s.p.resize(g.cells());
  for (std::size_t i = 0; i < s.p.size(); ++i) s.p[i] = std::sin(1.0 + double(i));
  s.u = make_face_vector(g);
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < s.u[a].size(); ++f) s.u[a][f] = std::cos(double(a) + 0.1 * double(f));
  s.drag.beta.resize(g.cells());
  for (std::size_t i = 0; i < s.drag.beta.size(); ++i) s.drag.beta[i] = 1e3 / (1.0 + double(i));
  for (int a = 0; a < 3; ++a) s.drag.beta_v[a].assign(g.cells(), 0.25 * (a + 1));
  return s;
}

const std::string kHash(64, 'a');

TEST(Checkpoint, RoundTripRestoresEveryValueAndCounter) {
  const auto dir = test_support::fresh_scratch_dir("checkpoint", "roundtrip");
  const Grid g = small_grid();
  const FlowState s = sample_state(g);
  const LoopCounters c{17, {1.5, 1.25, 1.125}, 0.3, 0.7};
  write_checkpoint(dir / "c.bin", kHash, g, s, c);
  auto r = read_checkpoint(dir / "c.bin", kHash, g);
  ASSERT_TRUE(std::holds_alternative<Checkpoint>(r)) << std::get<std::string>(r);
  const Checkpoint& cp = std::get<Checkpoint>(r);
  EXPECT_EQ(cp.counters.iteration, 17);
  EXPECT_EQ(cp.counters.qoi_history, c.qoi_history);
  EXPECT_EQ(cp.counters.first_continuity, 0.3);
  EXPECT_EQ(cp.counters.first_momentum, 0.7);
  EXPECT_EQ(cp.state.p, s.p);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(cp.state.u[a].values, s.u[a].values);
  EXPECT_EQ(cp.state.drag.beta, s.drag.beta);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(cp.state.drag.beta_v[a], s.drag.beta_v[a]);
  EXPECT_FALSE(fs::exists(dir / ("c.bin.tmp." + std::to_string(::getpid()))));
}

TEST(Checkpoint, AnotherJobOrGridIsRefused) {
  const auto dir = test_support::fresh_scratch_dir("checkpoint", "foreign");
  const Grid g = small_grid();
  write_checkpoint(dir / "c.bin", kHash, g, sample_state(g), {3, {}, 1, 1});
  auto other_job = read_checkpoint(dir / "c.bin", std::string(64, 'b'), g);
  ASSERT_TRUE(std::holds_alternative<std::string>(other_job));
  EXPECT_NE(std::get<std::string>(other_job).find("belongs to job"), std::string::npos);
  Grid finer = g;
  finer.n = {6, 8, 4};
  auto other_grid = read_checkpoint(dir / "c.bin", kHash, finer);
  ASSERT_TRUE(std::holds_alternative<std::string>(other_grid));
  EXPECT_NE(std::get<std::string>(other_grid).find("grid"), std::string::npos);
}

TEST(Checkpoint, TruncatedAlteredOrMissingFilesAreRefused) {
  const auto dir = test_support::fresh_scratch_dir("checkpoint", "corrupt");
  const Grid g = small_grid();
  write_checkpoint(dir / "c.bin", kHash, g, sample_state(g), {3, {}, 1, 1});
  std::ifstream in(dir / "c.bin", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "short.bin", std::ios::binary) << bytes.substr(0, bytes.size() - 100);
  std::string altered = bytes;
  altered[40] = static_cast<char>(altered[40] ^ 1);  // inside the header
  std::ofstream(dir / "altered.bin", std::ios::binary) << altered;
  std::ofstream(dir / "text.bin") << "hello";
  for (const char* name : {"short.bin", "altered.bin", "text.bin", "missing.bin"}) {
    auto r = read_checkpoint(dir / name, kHash, g);
    EXPECT_TRUE(std::holds_alternative<std::string>(r)) << name;
  }
}

}  // namespace
}  // namespace gridfree
