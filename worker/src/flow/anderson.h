// SPDX-License-Identifier: GPL-3.0-or-later
// Anderson acceleration of the SIMPLEC fixed-point map (an opt-in
// prototype, SimpleSettings::anderson_depth; docs/DESIGN.md records what it
// measured).
//
// With x_k the iterate entering outer iteration k (u and p stacked), G the
// iteration and f_k = G(x_k) − x_k, depth m keeps the last m differences
// ΔF_i = f_{i+1} − f_i and ΔG_i = G(x_{i+1}) − G(x_i) and sets
//
//   γ = argmin ‖W (f_k − ΔF γ)‖₂,    x_{k+1} = G(x_k) − ΔG γ
//
// (Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715). W scales each block
// (u_x, u_y, u_z, p) by 1 / its RMS value in G(x_k), so pressure and
// velocity weigh alike. The small normal equations are solved with a
// relative Tikhonov term 1e-10 · trace. Sums are fixed-order
// (flow/parallel.h), so the result does not depend on the thread count.
#pragma once

#include <deque>
#include <vector>

#include "flow/fields.h"

namespace gridfree {

class AndersonMixer {
 public:
  explicit AndersonMixer(int depth) : depth_(depth) {}

  // x = the iterate before the iteration (as saved by pack), u, p = G(x)
  // on entry, the mixed iterate on return.
  void mix(const std::vector<double>& x, FaceVector& u, std::vector<double>& p);

  // u and p stacked into one vector.
  static void pack(const FaceVector& u, const std::vector<double>& p, std::vector<double>& out);

  void reset();

 private:
  int depth_;
  std::vector<double> last_f_, last_g_;
  std::deque<std::vector<double>> delta_f_, delta_g_;
};

}  // namespace gridfree
