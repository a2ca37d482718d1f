// SPDX-License-Identifier: GPL-3.0-or-later
// Legacy VTK writer (vtk_writer.h). Binary legacy VTK is big-endian float32.
#include "flow/vtk_writer.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace gridfree {
namespace {

void put_big_endian(std::ofstream& out, double value) {
  const float f = static_cast<float>(value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  if constexpr (std::endian::native == std::endian::little) bits = __builtin_bswap32(bits);
  out.write(reinterpret_cast<const char*>(&bits), sizeof bits);
}

void scalar(std::ofstream& out, const char* name, const std::vector<double>& values) {
  out << "SCALARS " << name << " float 1\nLOOKUP_TABLE default\n";
  for (double v : values) put_big_endian(out, v);
  out << '\n';
}

}  // namespace

void write_vtk(const std::filesystem::path& file, const Grid& grid, const std::vector<double>& eps_s,
               const FlowState& state) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "# vtk DataFile Version 3.0\ngridfree frozen-bed solution (CGS units)\nBINARY\n"
      << "DATASET STRUCTURED_POINTS\n"
      << "DIMENSIONS " << grid.n[0] + 1 << ' ' << grid.n[1] + 1 << ' ' << grid.n[2] + 1 << '\n'
      << "ORIGIN 0 0 0\n"
      << "SPACING " << grid.h(0) << ' ' << grid.h(1) << ' ' << grid.h(2) << '\n'
      << "CELL_DATA " << grid.cells() << '\n';
  scalar(out, "eps_s", eps_s);
  scalar(out, "eps_g", state.eps_g);
  scalar(out, "p", state.p);
  scalar(out, "beta", state.drag.beta);
  const auto u = cell_centre_velocity(grid, state.u);
  out << "VECTORS u_g float\n";
  for (std::size_t c = 0; c < grid.cells(); ++c)
    for (int a = 0; a < 3; ++a) put_big_endian(out, u[a][c]);
  out << '\n';
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace gridfree
