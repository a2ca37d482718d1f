// SPDX-License-Identifier: GPL-3.0-or-later
// FlowState ↔ checkpoint arrays (flow/checkpoint_fields.h).
#include "flow/checkpoint_fields.h"

namespace gridfree {
namespace {

const char* const kVelocity[3] = {"u_x", "u_y", "u_z"};
const char* const kBetaV[3] = {"beta_v_x", "beta_v_y", "beta_v_z"};

}  // namespace

std::vector<CheckpointArray> checkpoint_arrays(const FlowState& s) {
  std::vector<CheckpointArray> out;
  out.push_back({"p", {s.p.begin(), s.p.end()}});
  for (int a = 0; a < 3; ++a) out.push_back({kVelocity[a], {s.u[a].values.begin(), s.u[a].values.end()}});
  out.push_back({"beta", {s.drag.beta.begin(), s.drag.beta.end()}});
  for (int a = 0; a < 3; ++a) out.push_back({kBetaV[a], {s.drag.beta_v[a].begin(), s.drag.beta_v[a].end()}});
  return out;
}

bool checkpoint_sizes_match(const Grid& grid, const std::vector<CheckpointArray>& arrays, std::string& why) {
  std::vector<std::pair<std::string, std::size_t>> want = {{"p", grid.cells()}};
  for (int a = 0; a < 3; ++a) want.push_back({kVelocity[a], FaceLayout(grid, a).size()});
  want.push_back({"beta", grid.cells()});
  for (int a = 0; a < 3; ++a) want.push_back({kBetaV[a], grid.cells()});
  if (arrays.size() != want.size()) {
    why = "it holds " + std::to_string(arrays.size()) + " arrays, not " + std::to_string(want.size());
    return false;
  }
  for (std::size_t i = 0; i < want.size(); ++i) {
    const bool optional = i >= 5;  // beta_v: empty without particles
    if (arrays[i].name != want[i].first ||
        (arrays[i].values.size() != want[i].second && !(optional && arrays[i].values.empty()))) {
      why = "array " + std::to_string(i) + " is '" + arrays[i].name + "' of " +
            std::to_string(arrays[i].values.size()) + " values, not '" + want[i].first + "' of " +
            std::to_string(want[i].second);
      return false;
    }
  }
  return true;
}

void restore_checkpoint_arrays(const Grid& grid, std::vector<CheckpointArray> arrays, FlowState& s) {
  s.p = std::move(arrays[0].values);
  s.u = make_face_vector(grid);
  for (int a = 0; a < 3; ++a) s.u[a].values = std::move(arrays[1 + a].values);
  s.drag.beta = std::move(arrays[4].values);
  for (int a = 0; a < 3; ++a) s.drag.beta_v[a] = std::move(arrays[5 + a].values);
}

}  // namespace gridfree
