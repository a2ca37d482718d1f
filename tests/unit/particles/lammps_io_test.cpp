// SPDX-License-Identifier: GPL-3.0-or-later
// LAMMPS / LIGGGHTS dumps: the chosen snapshot's particles in cm relative to
// the box's low corner, whatever the column order or coordinate style; a
// box that differs from the case's domain and malformed dumps are
// InputErrors naming the file and line.
#include <gtest/gtest.h>

#include <fstream>

#include "particles/particle_io.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

fs::path write(const std::string& name, const std::string& text) {
  const fs::path file = test_support::fresh_scratch_dir("lammps_io", name) / "dump.txt";
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// Two snapshots of a box [-0.5, 0.5] x [0, 2] x [1, 1.5] (m, `units si`).
const char* kTwoSnapshots =
    "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp ff pp\n"
    "-0.5 0.5\n0 2\n1 1.5\n"
    "ITEM: ATOMS id type x y z radius vx vy vz\n"
    "1 1 0.0 0.5 1.25 0.005 0.1 0.2 0.3\n"
    "2 1 0.25 1.5 1.1 0.005 0 0 0\n"
    "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp ff pp\n"
    "-0.5 0.5\n0 2\n1 1.5\n"
    "ITEM: ATOMS radius z y x id\n"
    "0.01 1.4 1.0 -0.4 7\n";

std::string where_of(const fs::path& file, const LammpsOptions& o) {
  try {
    read_lammps_dump(file, o);
  } catch (const InputError& e) {
    return e.problems().at(0).where + " " + e.problems().at(0).reason;
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(LammpsDump, ChosenSnapshotInCentimetresFromTheBoxCorner) {
  const fs::path file = write("two", kTwoSnapshots);
  const ParticleSet first = read_lammps_dump(file, {100.0, 100});
  ASSERT_EQ(first.particles.size(), 2u);
  EXPECT_TRUE(first.has_velocity);
  const Particle& p = first.particles[0];
  // x: (0 − (−0.5)) m = 50 cm; z: (1.25 − 1) m = 25 cm; d = 2 × 0.005 m = 1 cm.
  EXPECT_DOUBLE_EQ(p.x, 50.0);
  EXPECT_DOUBLE_EQ(p.y, 50.0);
  EXPECT_DOUBLE_EQ(p.z, 25.0);
  EXPECT_DOUBLE_EQ(p.d, 1.0);
  EXPECT_DOUBLE_EQ(p.w, 30.0);  // 0.3 m/s
  EXPECT_EQ(first.source_lines[1], 11);
  ASSERT_TRUE(first.box_cm.has_value());
  EXPECT_DOUBLE_EQ((*first.box_cm)[0], 100.0);
  EXPECT_DOUBLE_EQ((*first.box_cm)[2], 50.0);

  // Default: the last snapshot, whose columns come in another order.
  const ParticleSet last = read_lammps_dump(file, {100.0, std::nullopt});
  ASSERT_EQ(last.particles.size(), 1u);
  EXPECT_FALSE(last.has_velocity);
  EXPECT_DOUBLE_EQ(last.particles[0].x, 10.0);
  EXPECT_DOUBLE_EQ(last.particles[0].z, 40.0);
  EXPECT_DOUBLE_EQ(last.particles[0].d, 2.0);
}

TEST(LammpsDump, ScaledCoordinatesAndDiameterInCgs) {
  const fs::path file = write("scaled",
                              "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n"
                              "2 6\n0 10\n-1 1\nITEM: ATOMS id xs ys zs diameter\n1 0.25 0.5 0.75 0.1\n");
  const ParticleSet set = read_lammps_dump(file, {1.0, std::nullopt});
  ASSERT_EQ(set.particles.size(), 1u);
  EXPECT_DOUBLE_EQ(set.particles[0].x, 1.0);
  EXPECT_DOUBLE_EQ(set.particles[0].y, 5.0);
  EXPECT_DOUBLE_EQ(set.particles[0].z, 1.5);
  EXPECT_DOUBLE_EQ(set.particles[0].d, 0.1);
}

TEST(LammpsDump, MalformedDumpsNameTheLine) {
  const std::string head = "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n";
  const fs::path missing_timestep = write("ts", kTwoSnapshots);
  EXPECT_NE(where_of(missing_timestep, {100.0, 150}).find("no snapshot at timestep 150 (the file has 100, 200)"),
            std::string::npos);

  const fs::path no_size = write("size", head + "ITEM: ATOMS id x y z\n1 0.1 0.1 0.1\n2 0.2 0.2 0.2\n");
  EXPECT_NE(where_of(no_size, {1.0, std::nullopt}).find(":9 the ATOMS columns lack the particle size"), std::string::npos);

  const fs::path short_row = write("short", head + "ITEM: ATOMS x y z radius\n0.1 0.1 0.1 0.01\n0.2 0.2 0.01\n");
  EXPECT_NE(where_of(short_row, {1.0, std::nullopt}).find(":11 expected 4 columns, got 3"), std::string::npos);

  const fs::path truncated = write("trunc", head + "ITEM: ATOMS x y z radius\n0.1 0.1 0.1 0.01\n");
  EXPECT_NE(where_of(truncated, {1.0, std::nullopt}).find("the file ends where an atom line was expected"),
            std::string::npos);

  const fs::path bad_number = write("num", head + "ITEM: ATOMS x y z radius\n0.1 0.1 0.1 0.01\n0.2 nan 0.2 0.01\n");
  EXPECT_NE(where_of(bad_number, {1.0, std::nullopt}).find(":11 position: 'nan' is not a finite number"),
            std::string::npos);

  const fs::path triclinic =
      write("tri", "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n0\nITEM: BOX BOUNDS xy xz yz pp pp pp\n");
  EXPECT_NE(where_of(triclinic, {1.0, std::nullopt}).find(":5 triclinic"), std::string::npos);

  const fs::path empty = write("empty", "\n\n");
  EXPECT_NE(where_of(empty, {1.0, std::nullopt}).find("no snapshot in the file"), std::string::npos);

  const fs::path huge_count = write("count", "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n1e300\n");
  EXPECT_NE(where_of(huge_count, {1.0, std::nullopt}).find(":4 the number of atoms must be one whole number"),
            std::string::npos);
}

TEST(LammpsDump, LoadedOnlyWhenTheBoxIsTheCasesDomain) {
  // One particle in a 1 × 1 × 1 cm box (cgs); the case's domain is 10 × 10 × 10 d with d = 0.1 cm.
  const fs::path file = write("load",
                              "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n"
                              "0 1\n0 1\n0 1\nITEM: ATOMS x y z radius\n0.5 0.5 0.5 0.05\n");
  CaseSpec c;
  c.particle_diameter_cm = 0.1;
  c.domain_dp = {10, 10, 10};
  FileSpec source{file, "lammps", "cgs", std::nullopt};
  EXPECT_EQ(load_particles(source, c).particles.size(), 1u);
  c.domain_dp = {10, 20, 10};
  try {
    load_particles(source, c);
    ADD_FAILURE() << "a box of 1 cm along y loaded into a 2 cm domain";
  } catch (const InputError& e) {
    EXPECT_NE(e.problems().at(0).reason.find("the box is 1 cm along y but the case's domain is 2 cm"), std::string::npos)
        << e.problems().at(0).reason;
  }
  source.units = "";
  EXPECT_THROW(load_particles(source, c), InputError);
}

}  // namespace
}  // namespace gridfree
