// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/prolong.h"

#include <cmath>

namespace gridfree {
namespace {

// The two lattice points around coordinate x along one axis and the weight
// of the second: points at (i + offset) Δ, i = 0 … m−1.
struct Bracket {
  int i0 = 0, i1 = 0;
  double w = 0;
};

Bracket bracket(double x, double h, double offset, int m, bool periodic) {
  const double t = x / h - offset;
  if (periodic) {
    const double fl = std::floor(t);
    int i0 = static_cast<int>(fl) % m;
    if (i0 < 0) i0 += m;
    return {i0, (i0 + 1) % m, t - fl};
  }
  if (t <= 0) return {0, 0, 0};
  if (t >= m - 1) return {m - 1, m - 1, 0};
  const int i0 = static_cast<int>(std::floor(t));
  return {i0, i0 + 1, t - i0};
}

// Trilinear interpolant at x of values on a lattice with `m` points and
// `offset` per axis; index(i, j, k) as the field stores them.
template <class Index>
double interpolate(const std::array<double, 3>& x, const Grid& g, const std::array<double, 3>& offset,
                   const std::array<int, 3>& m, const std::vector<double>& values, Index index) {
  std::array<Bracket, 3> br;
  for (int b = 0; b < 3; ++b) br[b] = bracket(x[b], g.h(b), offset[b], m[b], g.periodic[b]);
  double sum = 0;
  for (int c = 0; c < 8; ++c) {
    const int i = (c & 1) ? br[0].i1 : br[0].i0;
    const int j = (c & 2) ? br[1].i1 : br[1].i0;
    const int k = (c & 4) ? br[2].i1 : br[2].i0;
    const double w = ((c & 1) ? br[0].w : 1 - br[0].w) * ((c & 2) ? br[1].w : 1 - br[1].w) *
                     ((c & 4) ? br[2].w : 1 - br[2].w);
    if (w != 0.0) sum += w * values[index(i, j, k)];
  }
  return sum;
}

}  // namespace

CellField prolong_cells(const Grid& coarse, const CellField& values, const Grid& fine) {
  CellField out(fine.cells());
  const long n = static_cast<long>(out.size());
#pragma omp parallel for schedule(static)
  for (long c = 0; c < n; ++c) {
    const auto x = cell_coords(fine, std::size_t(c));
    const std::array<double, 3> pos{fine.centre(0, x[0]), fine.centre(1, x[1]), fine.centre(2, x[2])};
    out[std::size_t(c)] = interpolate(pos, coarse, {0.5, 0.5, 0.5}, coarse.n, values,
                                      [&](int i, int j, int k) { return coarse.index(i, j, k); });
  }
  return out;
}

FaceVector prolong_faces(const Grid& coarse, const FaceVector& values, const Grid& fine) {
  FaceVector out = make_face_vector(fine);
  for (int a = 0; a < 3; ++a) {
    const FaceLayout& from = values[a].layout;
    const FaceLayout& to = out[a].layout;
    std::array<double, 3> offset{0.5, 0.5, 0.5};
    offset[a] = 0.0;
    const long n = static_cast<long>(to.size());
#pragma omp parallel for schedule(static)
    for (long f = 0; f < n; ++f) {
      const auto x = face_coords(to, std::size_t(f));
      std::array<double, 3> pos{};
      for (int b = 0; b < 3; ++b) pos[b] = b == a ? x[b] * fine.h(b) : fine.centre(b, x[b]);
      out[a][std::size_t(f)] = interpolate(pos, coarse, offset, from.n, values[a].values,
                                           [&](int i, int j, int k) { return from.index(i, j, k); });
    }
  }
  return out;
}

}  // namespace gridfree
