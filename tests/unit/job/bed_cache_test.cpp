// SPDX-License-Identifier: GPL-3.0-or-later
// The bed cache (job/bed_cache.h): a stored bed is the generated one bit for
// bit, the key separates every input a generator reads, and a damaged file
// is never used.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "job/bed_cache.h"
#include "scratch_dir.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// A random bed of about 1 200 particles: milliseconds to generate (what is
// tested is the cache, not the generator).
GeneratorSpec small_bed(int seed = 3) {
  return {"uniform_random", {{"kind", "uniform_random"}, {"seed", seed}, {"solids_fraction", 0.2}}, "/generator"};
}

// Every double of every particle and every region field, compared by bits.
void expect_same_bed(const GeneratedParticles& a, const GeneratedParticles& b) {
  ASSERT_EQ(a.set.particles.size(), b.set.particles.size());
  EXPECT_EQ(std::memcmp(a.set.particles.data(), b.set.particles.data(), a.set.particles.size() * sizeof(Particle)), 0);
  EXPECT_EQ(a.set.has_velocity, b.set.has_velocity);
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    EXPECT_EQ(a.regions[i].name, b.regions[i].name);
    EXPECT_EQ(a.regions[i].count, b.regions[i].count);
    EXPECT_EQ(a.regions[i].volume_cm3, b.regions[i].volume_cm3);
    EXPECT_EQ(a.regions[i].target_fraction, b.regions[i].target_fraction);
    EXPECT_EQ(a.regions[i].solids_fraction, b.regions[i].solids_fraction);
  }
}

TEST(BedCache, AStoredBedReadsBackBitForBit) {
  const auto dir = test_support::fresh_scratch_dir("bed_cache", "roundtrip");
  const CaseSpec c = test_support::sscp_bed_case();
  const GeneratedParticles bed = generate_particles_with_report(small_bed(), c);
  ASSERT_GT(bed.set.particles.size(), 1000u);
  const std::string key = bed_cache_key(small_bed(), c, "program");
  const fs::path file = bed_cache_file(dir, key);
  write_cached_bed(file, key, bed);
  std::string why;
  const auto back = read_cached_bed(file, key, why);
  ASSERT_TRUE(back) << why;
  expect_same_bed(bed, *back);
  EXPECT_FALSE(read_cached_bed(dir / "none.bed", key, why));
  EXPECT_EQ(why, "") << "a missing file is no problem";
}

TEST(BedCache, TheKeyChangesWithEveryInputOfTheGenerator) {
  const CaseSpec c = test_support::sscp_bed_case();
  const std::string base = bed_cache_key(small_bed(), c, "program");
  EXPECT_EQ(base, bed_cache_key(small_bed(), c, "program"));
  EXPECT_NE(base, bed_cache_key(small_bed(4), c, "program"));
  EXPECT_NE(base, bed_cache_key(small_bed(), c, "another build"));
  CaseSpec longer = c;
  longer.domain_dp[1] = 41;
  EXPECT_NE(base, bed_cache_key(small_bed(), longer, "program"));
  CaseSpec finer = c;
  finer.particle_diameter_cm = 0.3257;
  EXPECT_NE(base, bed_cache_key(small_bed(), finer, "program"));
  CaseSpec periodic = c;
  periodic.boundaries[0] = {BoundarySpec{BoundaryKind::kPeriodic, 0, 0}, BoundarySpec{BoundaryKind::kPeriodic, 0, 0}};
  EXPECT_NE(base, bed_cache_key(small_bed(), periodic, "program"));
  // What the generator does not read leaves the key alone: a job's gas and
  // probes, so every job of a case shares its bed.
  CaseSpec other_gas = c;
  other_gas.gas.viscosity_g_cm_s *= 2;
  other_gas.probes.y2_dp = 30;
  EXPECT_EQ(base, bed_cache_key(small_bed(), other_gas, "program"));
}

TEST(BedCache, ADamagedOrForeignFileIsRefusedWithItsReason) {
  const auto dir = test_support::fresh_scratch_dir("bed_cache", "damaged");
  const CaseSpec c = test_support::sscp_bed_case();
  const GeneratedParticles bed = generate_particles_with_report(small_bed(), c);
  const std::string key = bed_cache_key(small_bed(), c, "program");
  const fs::path file = dir / "bed.bed";
  std::string why;

  write_cached_bed(file, key, bed);
  EXPECT_FALSE(read_cached_bed(file, bed_cache_key(small_bed(4), c, "program"), why));
  EXPECT_NE(why.find("another bed"), std::string::npos) << why;

  {  // one flipped bit in the last particle's diameter
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-static_cast<std::streamoff>(4 * sizeof(double)), std::ios::end);
    char b = 0;
    f.read(&b, 1);
    b = static_cast<char>(b ^ 1);
    f.seekp(-static_cast<std::streamoff>(4 * sizeof(double)), std::ios::end);
    f.write(&b, 1);
  }
  EXPECT_FALSE(read_cached_bed(file, key, why));
  EXPECT_EQ(why, "checksum mismatch");

  write_cached_bed(file, key, bed);
  fs::resize_file(file, fs::file_size(file) - 8);
  EXPECT_FALSE(read_cached_bed(file, key, why));
  EXPECT_NE(why.find("bytes of particles"), std::string::npos) << why;

  {  // a header that states a count far beyond the file: refused before allocating for it
    std::ofstream f(file, std::ios::trunc);
    f << "gridfree-bed 1\n" << key << "\n{\"count\":1000000000000000,\"regions\":[],\"payload_sha256\":\"x\"}\n";
  }
  EXPECT_FALSE(read_cached_bed(file, key, why));
  EXPECT_NE(why.find("bytes of particles"), std::string::npos) << why;

  std::ofstream(file) << "something else\n";
  EXPECT_FALSE(read_cached_bed(file, key, why));
  EXPECT_EQ(why, "not a gridfree bed file");
}

TEST(BedCache, TheGeneratorStoresOnceReusesAndReplacesADamagedFile) {
  const auto dir = test_support::fresh_scratch_dir("bed_cache", "generator");
  const CaseSpec c = test_support::sscp_bed_case();
  const GeneratedParticles fresh = generate_particles_with_report(small_bed(), c);
  const BedGenerator cached = cached_bed_generator(dir, 0.0);
  expect_same_bed(fresh, cached(small_bed(), c));
  const fs::path file = bed_cache_file(dir, bed_cache_key(small_bed(), c, executable_sha256()));
  ASSERT_TRUE(fs::exists(file));
  // The stored file is what the second call returns: replace its bed by
  // another seed's under the same key, and that one comes back.
  const GeneratedParticles other = generate_particles_with_report(small_bed(4), c);
  write_cached_bed(file, bed_cache_key(small_bed(), c, executable_sha256()), other);
  expect_same_bed(other, cached(small_bed(), c));
  // A damaged file is generated again and replaced.
  fs::resize_file(file, fs::file_size(file) - 1);
  expect_same_bed(fresh, cached(small_bed(), c));
  std::string why;
  ASSERT_TRUE(read_cached_bed(file, bed_cache_key(small_bed(), c, executable_sha256()), why)) << why;
  // A bed faster to make than the threshold is not stored.
  const BedGenerator thrifty = cached_bed_generator(dir / "thrifty", 1e9);
  expect_same_bed(fresh, thrifty(small_bed(), c));
  EXPECT_FALSE(fs::exists(dir / "thrifty"));
  // The executable's identity is its content's SHA-256.
  EXPECT_EQ(executable_sha256().size(), 64u);
}

}  // namespace
}  // namespace gridfree
