// SPDX-License-Identifier: GPL-3.0-or-later
// reshape_stencil (linalg/stencil.h): one system serves grids of different
// sizes in turn — every array takes the new grid's cell count, the grid is
// replaced, and a system shrunk and grown back keeps its storage.
#include <gtest/gtest.h>

#include "linalg/stencil.h"

namespace gridfree {
namespace {

Grid grid_of(int nx, int ny, int nz) {
  Grid g;
  g.n = {nx, ny, nz};
  return g;
}

void expect_sized(const Stencil7& s, std::size_t n) {
  for (const auto* v : {&s.ap, &s.aw, &s.ae, &s.as, &s.an, &s.ab, &s.at, &s.b}) EXPECT_EQ(v->size(), n);
  EXPECT_EQ(s.grid.cells(), n);
}

TEST(ReshapeStencil, ArraysFollowTheGridAndStorageIsKept) {
  Stencil7 s(grid_of(5, 4, 3));  // 60 cells, like the largest face grid
  const double* storage = s.ap.data();
  reshape_stencil(s, grid_of(4, 4, 3));  // 48 cells
  expect_sized(s, 48);
  EXPECT_EQ(s.grid.n, (std::array<int, 3>{4, 4, 3}));
  reshape_stencil(s, grid_of(4, 5, 3));  // 60 cells again: no reallocation
  expect_sized(s, 60);
  EXPECT_EQ(s.ap.data(), storage);
}

}  // namespace
}  // namespace gridfree
