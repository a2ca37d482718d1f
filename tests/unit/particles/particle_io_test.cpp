// SPDX-License-Identifier: GPL-3.0-or-later
// Particle files: CSV round trips are exact; an MFiX particle_input.dat
// (both the headerless 2016 format and the "Version 2.0" format) gives the
// positions written into it; malformed files and impossible configurations
// are InputErrors that name the file and line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "particles/particle_io.h"
#include "particles/random.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

class ParticleFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("gridfree_particle_io_") + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  // The problems of an InputError thrown by f (a test failure otherwise).
  template <class F>
  std::vector<Problem> problems_of(F&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.problems();
    }
    ADD_FAILURE() << "no InputError";
    return {};
  }
  fs::path dir_;
};

CaseSpec cube_case(double side_cm) {
  CaseSpec c;
  c.particle_diameter_cm = 0.1;
  c.domain_dp = {side_cm / 0.1, side_cm / 0.1, side_cm / 0.1};
  const BoundarySpec periodic{BoundaryKind::kPeriodic, 0, 0};
  c.boundaries[0] = {periodic, periodic};
  c.boundaries[2] = {periodic, periodic};
  return c;
}

TEST_F(ParticleFiles, CsvRoundTripIsExact) {
  ParticleSet set;
  ParticleRandom rng(42);
  for (int i = 0; i < 200; ++i) {
    // Awkward doubles: 17 significant digits, tiny and large magnitudes.
    const double scale = std::pow(10.0, static_cast<int>(rng.below(20)) - 10);
    set.particles.push_back({rng.uniform() * scale, rng.uniform(), 1.0 / 3.0 + i, 0.01 + rng.uniform() * 1e-3,
                             rng.normal(), -rng.normal() * 1e-300, std::numeric_limits<double>::denorm_min()});
  }
  set.has_velocity = true;
  const fs::path file = dir_ / "set.csv";
  write_csv(file, set);
  const ParticleSet back = read_csv(file);
  ASSERT_EQ(back.particles.size(), set.particles.size());
  EXPECT_TRUE(back.has_velocity);
  for (std::size_t i = 0; i < set.particles.size(); ++i) {
    const Particle& a = set.particles[i];
    const Particle& b = back.particles[i];
    EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z && a.d == b.d && a.u == b.u && a.v == b.v && a.w == b.w) << i;
    EXPECT_EQ(back.source_lines[i], static_cast<int>(i) + 2);  // line 1 is the header
  }
  set.has_velocity = false;
  write_csv(file, set);
  EXPECT_FALSE(read_csv(file).has_velocity);
}

TEST_F(ParticleFiles, CsvHeaderInAnyOrderOrNoHeader) {
  const ParticleSet a = read_csv(write("a.csv", "# a comment\nd, z ,y,x\n0.1,3,2,1\n\n0.2,6,5,4\n"));
  ASSERT_EQ(a.particles.size(), 2u);
  EXPECT_EQ(a.particles[1].x, 4);
  EXPECT_EQ(a.particles[1].z, 6);
  EXPECT_EQ(a.particles[1].d, 0.2);
  EXPECT_EQ(a.source_lines[1], 5);
  const ParticleSet b = read_csv(write("b.csv", "1,2,3,0.1,0.5,0.6,0.7\r\n"));
  ASSERT_EQ(b.particles.size(), 1u);
  EXPECT_TRUE(b.has_velocity);
  EXPECT_EQ(b.particles[0].w, 0.7);
}

TEST_F(ParticleFiles, MalformedCsvNamesTheLine) {
  const fs::path bad_number = write("n.csv", "x,y,z,d\n1,2,3,0.1\n1,two,3,0.1\n");
  auto p = problems_of([&] { read_csv(bad_number); });
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].where, bad_number.string() + ":3");
  EXPECT_NE(p[0].reason.find("column y"), std::string::npos) << p[0].reason;

  const fs::path columns = write("c.csv", "x,y,z,d\n1,2,3,0.1\n1,2,3\n");
  p = problems_of([&] { read_csv(columns); });
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].where, columns.string() + ":3");

  const fs::path diameter = write("d.csv", "x,y,z,d\n1,2,3,0\n4,5,6,-1\n");
  p = problems_of([&] { read_csv(diameter); });
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].where, diameter.string() + ":2");
  EXPECT_EQ(p[1].where, diameter.string() + ":3");

  const fs::path header = write("h.csv", "x,y,d\n1,2,0.1\n");
  EXPECT_EQ(problems_of([&] { read_csv(header); })[0].where, header.string() + ":1");
  EXPECT_THROW(read_csv(dir_ / "absent.csv"), InputError);
}

TEST_F(ParticleFiles, MfixVersion1GivesTheSamePositions) {
  // x y z radius density [u v w], blanks and a Fortran exponent as MFiX writes them.
  const fs::path dat = write("particle_input.dat",
                             "  0.15  0.25  0.35  0.05  2.5\n"
                             "0.45 0.55 0.65 0.05 2.5 1.0 -2.0 3.0\n"
                             "\n"
                             "7.5D-01 0.85 0.95 0.5E-1 2.5\n");
  const ParticleSet set = read_mfix(dat);
  ASSERT_EQ(set.particles.size(), 3u);
  EXPECT_TRUE(set.has_velocity);
  const double expected[3][4] = {{0.15, 0.25, 0.35, 0.1}, {0.45, 0.55, 0.65, 0.1}, {0.75, 0.85, 0.95, 0.1}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(set.particles[i].x, expected[i][0]);
    EXPECT_EQ(set.particles[i].y, expected[i][1]);
    EXPECT_EQ(set.particles[i].z, expected[i][2]);
    EXPECT_EQ(set.particles[i].d, expected[i][3]);  // 2 × radius, exact in binary
  }
  EXPECT_EQ(set.particles[1].v, -2.0);
  EXPECT_EQ(set.source_lines[2], 4);

  // MFiX → CSV → read back: the same numbers.
  const fs::path csv = dir_ / "converted.csv";
  write_csv(csv, set);
  const ParticleSet back = read_csv(csv);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(back.particles[i].x, set.particles[i].x);
  // And our own MFiX writer round-trips.
  write_mfix(dir_ / "again.dat", set, 2.5);
  const ParticleSet again = read_mfix(dir_ / "again.dat");
  for (int i = 0; i < 3; ++i) EXPECT_EQ(again.particles[i].z, set.particles[i].z);
}

TEST_F(ParticleFiles, MfixVersion2Header) {
  std::string text = "Version 2.0\n";
  for (int i = 2; i <= 18; ++i) text += "instruction line " + std::to_string(i) + "\n";
  text +=
      "Dimension:    3\n"
      "Particles:    2\n"
      "==========\n"
      "Variable      Read(T/F)     Default value (when Read=F)\n"
      "==========\n"
      "Coordinates:     T          Must always be T\n"
      "Phase_ID:        F          1\n"
      "Diameter:        F          0.2\n"
      "Density:         T\n"
      "Velocity:        T\n"
      "Temperature:     T          (Ignored if energy eq. is not solved)\n"
      "Species:         T          (Ignored if species eq.  are not solved)\n"
      "User_Scalar:     T          (Ignored if no user scalars are defined)\n"
      "==========\n"
      "|  x  |  y  |  z  |  Density  |  u  |  v  |  w  |\n"
      "==========\n"
      "  1.00000000E-01  2.00000000E-01  3.00000000E-01  2.5  0.0  1.5  0.0\n"
      "  4.00000000E-01  5.00000000E-01  6.00000000E-01  2.5  0.0  0.0  0.0\n";
  const ParticleSet set = read_mfix(write("v2.dat", text));
  ASSERT_EQ(set.particles.size(), 2u);
  EXPECT_EQ(set.particles[1].x, 0.4);
  EXPECT_EQ(set.particles[1].d, 0.2);
  EXPECT_EQ(set.particles[0].v, 1.5);
  EXPECT_EQ(set.source_lines[0], 35);  // MFiX: "Data starts at line 35"
}

TEST_F(ParticleFiles, MalformedMfixNamesTheLine) {
  const fs::path dat = write("bad.dat", "0.1 0.2 0.3 0.05 2.5\n0.1 0.2 0.3 0.05\n0.4 0.5 0.6 -0.05 2.5\n");
  const auto p = problems_of([&] { read_mfix(dat); });
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].where, dat.string() + ":2");
  EXPECT_EQ(p[1].where, dat.string() + ":3");
  EXPECT_NE(p[1].reason.find("radius"), std::string::npos);
}

TEST_F(ParticleFiles, CheckParticlesNamesFileLines) {
  // Particle on line 3 overlaps line 2 (centres 0.05 apart, d = 0.1);
  // line 4 lies outside the 1 cm domain.
  const fs::path file = write("bed.csv", "x,y,z,d\n0.5,0.5,0.5,0.1\n0.55,0.5,0.5,0.1\n0.5,1.5,0.5,0.1\n");
  const ParticleSet set = read_csv(file);
  auto p = problems_of([&] { check_particles(set, cube_case(1.0)); });
  ASSERT_EQ(p.size(), 1u);  // positions first; overlaps once every centre is inside
  EXPECT_EQ(p[0].where, file.string() + ":4");

  ParticleSet inside = set;
  inside.particles.pop_back();
  p = problems_of([&] { check_particles(inside, cube_case(1.0)); });
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].where, file.string() + ":3");
  EXPECT_NE(p[0].reason.find(file.string() + ":2"), std::string::npos);

  // Overlap across the periodic x boundary: centres 0.02 and 0.96 are 0.06 apart.
  ParticleSet wrap;
  wrap.particles = {{0.02, 0.5, 0.5, 0.1, 0, 0, 0}, {0.96, 0.5, 0.5, 0.1, 0, 0, 0}};
  p = problems_of([&] { check_particles(wrap, cube_case(1.0)); });
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].where, "particle[1]");
  // Touching within the DEM tolerance (1 % overlap < 2 %) is accepted.
  wrap.particles[1].x = 0.02 + 0.099;
  EXPECT_NO_THROW(check_particles(wrap, cube_case(1.0)));
}

TEST_F(ParticleFiles, LoadParticlesFromEachSource) {
  CaseSpec c = cube_case(1.0);
  write("bed.csv", "x,y,z,d\n0.5,0.5,0.5,0.1\n");
  c.particles = FileSpec{dir_ / "bed.csv", "csv", "", std::nullopt};
  c.particle_velocity = {2.0, 9};
  const ParticleSet set = load_particles(c.particles, c);
  ASSERT_EQ(set.particles.size(), 1u);
  EXPECT_TRUE(set.has_velocity);
  EXPECT_NE(set.particles[0].u, 0.0);
  c.particles = UniformSpec{0.3};
  EXPECT_TRUE(load_particles(c.particles, c).particles.empty());
}

}  // namespace
}  // namespace gridfree
