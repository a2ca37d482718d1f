// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the particle file readers (particles/particle_io.h): the first byte
// picks CSV or MFiX, the rest is the file's content (written to a scratch
// file, as the readers take paths); then the configuration is checked
// against a small periodic case (domain, overlaps).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "particles/particle_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("gridfree_fuzz_particles_" + std::to_string(::getpid()));
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data) + 1, static_cast<std::streamsize>(size - 1));
  }
  try {
    const gridfree::ParticleSet set = (data[0] & 1) ? gridfree::read_mfix(file) : gridfree::read_csv(file);
    gridfree::CaseSpec c;
    c.domain_dp = {30, 200, 10};
    c.particle_diameter_cm = 0.01;
    for (int a : {0, 2}) c.boundaries[a] = {gridfree::BoundarySpec{gridfree::BoundaryKind::kPeriodic, 0, 0},
                                            gridfree::BoundarySpec{gridfree::BoundaryKind::kPeriodic, 0, 0}};
    gridfree::check_particles(set, c, {});
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
