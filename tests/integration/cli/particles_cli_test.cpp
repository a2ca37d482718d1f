// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree-worker particles` as users run it: a generator spec or a file to
// convert in, a CSV out, exit 0 with the per-region counts on stderr;
// invalid input exits 2 naming the JSON path (or file:line:col) and writes
// nothing.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

using gridfree::test_support::CommandRun;

CommandRun run_worker(const std::string& args, const fs::path& dir) {
  return gridfree::test_support::run_executable("gridfree-worker", args, dir);
}

using gridfree::test_support::slurp;

std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

class ParticlesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gridfree_particles_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  CommandRun particles(const fs::path& spec, const fs::path& out) {
    return run_worker("particles " + spec.string() + " -o " + out.string(), dir_);
  }
  fs::path dir_;
};

TEST_F(ParticlesCli, GeneratesTheBurstingBubble) {
  const auto spec = write("pc1.json", R"({"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
                                          "generator": {"kind": "bursting_bubble", "seed": 1}})");
  const CommandRun r = particles(spec, dir_ / "pc1.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurp(dir_ / "pc1.csv");
  EXPECT_EQ(csv.rfind("x,y,z,d\n", 0), 0u);
  EXPECT_EQ(count_lines(csv), 1u + 4649u);  // header + 4513 + 10 + 126
  EXPECT_NE(r.err.find("4649 particles"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("dense"), std::string::npos) << r.err;
  // Same spec, same bytes.
  ASSERT_EQ(particles(spec, dir_ / "again.csv").exit_code, 0);
  EXPECT_EQ(slurp(dir_ / "again.csv"), csv);
}

TEST_F(ParticlesCli, ThermalVelocitiesAddColumns) {
  const auto spec = write("pc3t.json", R"({"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
                                           "generator": {"kind": "bursting_bubble", "seed": 3},
                                           "particle_velocity": {"thermal_cm_s": 1.0, "seed": 3}})");
  ASSERT_EQ(particles(spec, dir_ / "pc3t.csv").exit_code, 0);
  EXPECT_EQ(slurp(dir_ / "pc3t.csv").rfind("x,y,z,d,u,v,w\n", 0), 0u);
}

TEST_F(ParticlesCli, ConvertsAnMfixFile) {
  write("particle_input.dat", "0.15 0.25 0.35 0.05 2.5\n0.45 0.55 0.65 0.05 2.5\n");
  const auto spec = write("convert.json", R"({"domain_dp": [10, 10, 10], "particle_diameter_cm": 0.1,
                                              "file": "particle_input.dat", "format": "mfix"})");
  const CommandRun r = particles(spec, dir_ / "converted.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "converted.csv"), "x,y,z,d\n0.14999999999999999,0.25,0.34999999999999998,0.10000000000000001\n"
                                           "0.45000000000000001,0.55000000000000004,0.65000000000000002,0.10000000000000001\n");
}

TEST_F(ParticlesCli, ConvertsALammpsDumpAndPrintsItsStructure) {
  // Two snapshots in SI units of a 1 × 1 × 1 cm box (10 d of 0.1 cm); the
  // one at timestep 100 is chosen, converted to cm and measured.
  write("dump.liggghts",
        "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.01\n0 0.01\n0 0.01\n"
        "ITEM: ATOMS id x y z radius\n1 0.002 0.003 0.004 0.0005\n2 0.006 0.003 0.004 0.0005\n"
        "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp ff\n0 0.01\n0 0.01\n0 0.01\n"
        "ITEM: ATOMS id x y z radius\n1 0.005 0.005 0.005 0.0005\n");
  const auto spec = write("dump.json", R"({"domain_dp": [10, 10, 10], "particle_diameter_cm": 0.1,
                                           "file": "dump.liggghts", "format": "lammps", "units": "si", "timestep": 100})");
  const CommandRun r = run_worker("particles " + spec.string() + " -o " + (dir_ / "dump.csv").string() + " --stats-json", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "dump.csv"), "x,y,z,d\n0.20000000000000001,0.29999999999999999,0.40000000000000002,0.10000000000000001\n"
                                      "0.59999999999999998,0.29999999999999999,0.40000000000000002,0.10000000000000001\n");
  const auto stats = nlohmann::json::parse(r.out);
  EXPECT_EQ(stats.at("particles"), 2);
  // Two particles 4 d apart along x: S/N = |1 + exp(i k 4d)|²/4 = 1 at a
  // period of 1 d and 2 d (in phase), the largest possible.
  EXPECT_NEAR(stats.at("largest_structure_factor").at("s_over_n").get<double>(), 1.0, 1e-12);
  EXPECT_EQ(stats.at("solids_fraction_y").at("values").size(), 10u);
  // Text form, without -o: nothing written, the same count.
  const CommandRun text = run_worker("particles " + spec.string() + " --stats", dir_);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(text.out.rfind("structure of 2 particles\n", 0), 0u) << text.out;
  // Neither -o nor --stats: exit 2 naming -o.
  const CommandRun none = run_worker("particles " + spec.string(), dir_);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("-o"), std::string::npos) << none.err;
}

// Numbers of two JSON documents equal to 1e-9 relative (1e-12 absolute),
// everything else exactly.
void expect_same_numbers(const nlohmann::json& a, const nlohmann::json& b, const std::string& where) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    EXPECT_NEAR(x, y, 1e-12 + 1e-9 * std::abs(y)) << where;
  } else if (a.is_structured() && b.is_structured() && a.type() == b.type() && a.size() == b.size()) {
    if (a.is_array()) {
      for (std::size_t i = 0; i < a.size(); ++i) expect_same_numbers(a[i], b[i], where + "/" + std::to_string(i));
    } else {
      for (const auto& [k, v] : a.items()) {
        ASSERT_TRUE(b.contains(k)) << where << "/" << k;
        expect_same_numbers(v, b.at(k), where + "/" + k);
      }
    }
  } else {
    EXPECT_EQ(a, b) << where;
  }
}

TEST_F(ParticlesCli, EveryFormatSolveReadsConvertsToTheSameBedAndStructure) {
  // One bed of 27 spheres (d = 0.1 cm, 10 d box) written in every format
  // `solve` reads: CSV, MFiX 2016 (headerless, radius), MFiX "Version 2.0"
  // (header, diameter from the header's default), a LAMMPS dump in SI
  // units and a LIGGGHTS-style dump in cgs with two snapshots, the first
  // selected by timestep. Each converts to the same positions (to rounding:
  // the SI dump is scaled by 100) and prints the same --stats-json.
  // Sites 0.3 cm apart, each moved by up to ±0.08 cm (a fixed LCG): no
  // overlaps, and no two axes with equal peaks (a tie would make the
  // reported axis depend on the last bit).
  std::vector<std::array<double, 3>> at;
  unsigned state = 12345;
  auto jitter = [&state] {
    state = state * 1103515245u + 12345u;
    return 0.16 * ((state >> 8) % 1000) / 999.0 - 0.08;
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        at.push_back({0.2 + 0.3 * i + jitter(), 0.2 + 0.3 * j + jitter(), 0.2 + 0.3 * k + jitter()});
  auto num = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  std::string csv = "x,y,z,d\n", v1, v2 = "Version 2.0\n", si, cgs;
  for (int i = 2; i <= 18; ++i) v2 += "instruction line " + std::to_string(i) + "\n";
  v2 += "Dimension: 3\nParticles: 27\n==========\nVariable Read(T/F) Default\n==========\n"
        "Coordinates: T\nPhase_ID: F 1\nDiameter: F 0.1\nDensity: F 2.5\nVelocity: F\nTemperature: F\n"
        "Species: F\nUser_Scalar: F\n==========\n| x | y | z |\n==========\n";
  const std::string box_si = "ITEM: BOX BOUNDS pp ff pp\n0 0.01\n0 0.01\n0 0.01\n";
  const std::string box_cgs = "ITEM: BOX BOUNDS pp ff pp\n-0.5 0.5\n0 1\n0 1\n";  // shifted in x: read relative to lo
  si = "ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n27\n" + box_si + "ITEM: ATOMS id type x y z radius\n";
  cgs = "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n27\n" + box_cgs + "ITEM: ATOMS id type radius z y x\n";
  for (std::size_t n = 0; n < at.size(); ++n) {
    const auto& p = at[n];
    csv += num(p[0]) + "," + num(p[1]) + "," + num(p[2]) + ",0.1\n";
    v1 += num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + " 0.05 2.5\n";
    v2 += num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + "\n";
    si += std::to_string(n + 1) + " 1 " + num(p[0] / 100) + " " + num(p[1] / 100) + " " + num(p[2] / 100) + " 0.0005\n";
    cgs += std::to_string(n + 1) + " 1 0.05 " + num(p[2]) + " " + num(p[1]) + " " + num(p[0] - 0.5) + "\n";
  }
  cgs += "ITEM: TIMESTEP\n2000\nITEM: NUMBER OF ATOMS\n1\n" + box_cgs + "ITEM: ATOMS id type radius z y x\n"
         "1 1 0.05 0.5 0.5 0\n";
  write("bed.csv", csv);
  write("v1.dat", v1);
  write("v2.dat", v2);
  write("si.dump", si);
  write("cgs.liggghts", cgs);
  const std::string head = R"({"domain_dp": [10, 10, 10], "particle_diameter_cm": 0.1, "boundaries": {"x": "periodic",
      "z": "periodic", "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 20}, "y_high": {"type":
      "pressure_outflow", "pressure_dyn_cm2": 0}}, )";
  const std::vector<std::pair<std::string, std::string>> sources = {
      {"csv", R"("file": "bed.csv", "format": "csv"})"},
      {"mfix1", R"("file": "v1.dat", "format": "mfix"})"},
      {"mfix2", R"("file": "v2.dat", "format": "mfix"})"},
      {"lammps_si", R"("file": "si.dump", "format": "lammps", "units": "si"})"},
      {"liggghts_cgs", R"("file": "cgs.liggghts", "format": "lammps", "units": "cgs", "timestep": 1000})"}};
  nlohmann::json reference;
  std::vector<std::vector<double>> reference_rows;
  for (const auto& [name, source] : sources) {
    const auto spec = write(name + ".json", head + source);
    const fs::path out = dir_ / (name + "_out.csv");
    const CommandRun r = run_worker("particles " + spec.string() + " -o " + out.string() + " --stats-json", dir_);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    std::vector<std::vector<double>> rows;
    std::istringstream in(slurp(out));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "x,y,z,d") << name;
    while (std::getline(in, line)) {
      std::vector<double> row;
      std::istringstream l(line);
      for (std::string c; std::getline(l, c, ',');) row.push_back(std::stod(c));
      rows.push_back(row);
    }
    const auto stats = nlohmann::json::parse(r.out);
    EXPECT_EQ(stats.at("particles"), 27) << name;
    if (reference.is_null()) {
      reference = stats;
      reference_rows = rows;
      continue;
    }
    ASSERT_EQ(rows.size(), reference_rows.size()) << name;
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(rows[i][c], reference_rows[i][c], 1e-12) << name << " row " << i;
    expect_same_numbers(stats, reference, name);
  }
}

TEST_F(ParticlesCli, UnknownGeneratorKindExits2) {
  const auto spec = write("bad.json", R"({"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
                                          "generator": {"kind": "bursting", "seed": 1}})");
  const CommandRun r = particles(spec, dir_ / "out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/generator/kind"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));
}

TEST_F(ParticlesCli, NegativeDomainExits2) {
  const auto spec = write("bad.json", R"({"domain_dp": [-30, 200, 10], "particle_diameter_cm": 0.01,
                                          "generator": {"kind": "bursting_bubble", "seed": 1}})");
  const CommandRun r = particles(spec, dir_ / "out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/domain_dp/0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));
}

TEST_F(ParticlesCli, ErrorsLeaveAnExistingOutputUntouched) {
  write("out.csv", "previous\n");
  write("bed.csv", "x,y,z,d\n0.5,0.5,0.5,0.1\n0.5,0.55,0.5,0.1\n");  // overlapping pair
  const auto spec = write("convert.json", R"({"domain_dp": [10, 10, 10], "particle_diameter_cm": 0.1,
                                              "file": "bed.csv", "format": "csv"})");
  const CommandRun r = particles(spec, dir_ / "out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bed.csv:3"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir_ / "out.csv"), "previous\n");
}

TEST_F(ParticlesCli, UnwritableOutputExits2NamingThePath) {
  const auto spec = write("spec.json", R"({"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
                                           "generator": {"kind": "bursting_bubble", "seed": 1}})");
  const fs::path missing = dir_ / "no_such_folder" / "out.csv";
  const CommandRun a = particles(spec, missing);
  EXPECT_EQ(a.exit_code, 2) << a.err;
  EXPECT_NE(a.err.find(missing.string()), std::string::npos) << a.err;
  EXPECT_NE(a.err.find("does not exist"), std::string::npos) << a.err;
  const CommandRun b = particles(spec, dir_);
  EXPECT_EQ(b.exit_code, 2) << b.err;
  EXPECT_NE(b.err.find("is an existing folder"), std::string::npos) << b.err;
}

TEST_F(ParticlesCli, MalformedJsonNamesLineAndColumn) {
  const auto spec = write("broken.json", "{\"domain_dp\": [30, 200, 10],\n \"particle_diameter_cm\": ,\n}");
  const CommandRun r = particles(spec, dir_ / "out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("broken.json:2:"), std::string::npos) << r.err;
}

}  // namespace
