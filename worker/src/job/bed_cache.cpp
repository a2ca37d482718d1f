// SPDX-License-Identifier: GPL-3.0-or-later
// Generated beds on disk (job/bed_cache.h).
//
// File layout, all on one host byte order (little-endian; a big-endian host
// stores nothing):
//   gridfree-bed 1\n
//   <key>\n
//   {"count":N,"has_velocity":…,"regions":[…],"payload_sha256":"…"}\n
//   N × 7 doubles: x y z d u v w
#include "job/bed_cache.h"

#include <unistd.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "job/job_hash.h"

namespace gridfree {
namespace {

constexpr const char* kBedMagic = "gridfree-bed 1";
constexpr std::size_t kDoublesPerParticle = 7;

std::string number17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::vector<double> payload_of(const ParticleSet& set) {
  std::vector<double> out;
  out.reserve(set.particles.size() * kDoublesPerParticle);
  for (const Particle& p : set.particles) out.insert(out.end(), {p.x, p.y, p.z, p.d, p.u, p.v, p.w});
  return out;
}

std::string_view bytes_of(const std::vector<double>& v) {
  return {reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double)};
}

nlohmann::json regions_json(const std::vector<RegionReport>& regions) {
  nlohmann::json out = nlohmann::json::array();
  for (const RegionReport& r : regions)
    out.push_back({{"name", r.name},
                   {"volume_cm3", r.volume_cm3},
                   {"target_fraction", r.target_fraction},
                   {"count", r.count},
                   {"solids_fraction", r.solids_fraction}});
  return out;
}

std::vector<RegionReport> regions_from(const nlohmann::json& j) {
  std::vector<RegionReport> out;
  for (const auto& r : j)
    out.push_back({r.at("name").get<std::string>(), r.at("volume_cm3").get<double>(),
                   r.at("target_fraction").get<double>(), r.at("count").get<std::size_t>(),
                   r.at("solids_fraction").get<double>()});
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string executable_sha256() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  if (!in) return "";
  Sha256 h;
  std::vector<char> buf(1 << 20);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    h.update(std::string_view(buf.data(), static_cast<std::size_t>(in.gcount())));
  }
  return h.hex_digest();
}

std::string bed_cache_key(const GeneratorSpec& spec, const CaseSpec& c, std::string_view program_id) {
  std::string text = std::string(kBedMagic) + "\n" + std::string(program_id) + "\n" + canonical_json(spec.params) + "\n";
  for (double l : c.domain_dp) text += number17(l) + " ";
  text += number17(c.particle_diameter_cm) + "\n";
  for (int a = 0; a < 3; ++a) text += c.periodic(a) ? 'p' : 'n';
  return sha256_hex(text);
}

std::filesystem::path bed_cache_file(const std::filesystem::path& dir, const std::string& key) {
  return dir / key.substr(0, 2) / (key + ".bed");
}

std::optional<GeneratedParticles> read_cached_bed(const std::filesystem::path& file, const std::string& key,
                                                  std::string& why) {
  why.clear();
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;  // not stored: no warning
  std::string magic, stored_key, header_line;
  if (!std::getline(in, magic) || magic != kBedMagic) {
    why = "not a gridfree bed file";
    return std::nullopt;
  }
  if (!std::getline(in, stored_key) || stored_key != key) {
    why = "holds another bed (key " + stored_key.substr(0, 12) + "…)";
    return std::nullopt;
  }
  if (!std::getline(in, header_line)) {
    why = "truncated header";
    return std::nullopt;
  }
  const nlohmann::json header = nlohmann::json::parse(header_line, nullptr, false);
  if (header.is_discarded() || !header.contains("count") || !header["count"].is_number_unsigned() ||
      !header.contains("payload_sha256") || !header["payload_sha256"].is_string()) {
    why = "unreadable header";
    return std::nullopt;
  }
  // The particles' size from the file itself, before allocating for the
  // count a damaged header may state.
  const auto count = header["count"].get<std::size_t>();
  std::error_code ec;
  const auto file_bytes = std::filesystem::file_size(file, ec);
  const auto at = static_cast<std::uintmax_t>(in.tellg());
  const std::uintmax_t stored = ec || file_bytes < at ? 0 : file_bytes - at;
  if (count > stored / (kDoublesPerParticle * sizeof(double)) ||
      stored != count * kDoublesPerParticle * sizeof(double)) {
    why = "holds " + std::to_string(stored) + " bytes of particles, not " +
          std::to_string(count * kDoublesPerParticle * sizeof(double));
    return std::nullopt;
  }
  std::vector<double> payload(count * kDoublesPerParticle);
  in.read(reinterpret_cast<char*>(payload.data()), static_cast<std::streamsize>(stored));
  if (static_cast<std::uintmax_t>(in.gcount()) != stored) {
    why = "could not read its particles";
    return std::nullopt;
  }
  if (sha256_hex(bytes_of(payload)) != header.value("payload_sha256", std::string())) {
    why = "checksum mismatch";
    return std::nullopt;
  }
  GeneratedParticles bed;
  try {
    bed.regions = regions_from(header.at("regions"));
  } catch (const nlohmann::json::exception&) {
    why = "unreadable regions";
    return std::nullopt;
  }
  bed.set.has_velocity = header.value("has_velocity", false);
  bed.set.particles.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double* v = &payload[i * kDoublesPerParticle];
    bed.set.particles[i] = {v[0], v[1], v[2], v[3], v[4], v[5], v[6]};
  }
  return bed;
}

void write_cached_bed(const std::filesystem::path& file, const std::string& key, const GeneratedParticles& bed) {
  if constexpr (std::endian::native != std::endian::little) throw std::runtime_error("big-endian host");
  const std::vector<double> payload = payload_of(bed.set);
  const nlohmann::json header = {{"count", bed.set.particles.size()},
                                 {"has_velocity", bed.set.has_velocity},
                                 {"regions", regions_json(bed.regions)},
                                 {"payload_sha256", sha256_hex(bytes_of(payload))}};
  std::filesystem::create_directories(file.parent_path());
  const auto tmp = file.parent_path() / (file.filename().string() + ".tmp." + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << kBedMagic << '\n' << key << '\n' << header.dump() << '\n';
    const auto bytes = bytes_of(payload);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::filesystem::rename(tmp, file);
}

BedGenerator cached_bed_generator(std::filesystem::path dir, double min_seconds) {
  return [dir = std::move(dir), min_seconds](const GeneratorSpec& spec, const CaseSpec& c) {
    const std::string program = executable_sha256();
    if (program.empty()) return generate_particles_with_report(spec, c);
    const std::string key = bed_cache_key(spec, c, program);
    const auto file = bed_cache_file(dir, key);
    std::string why;
    if (auto bed = read_cached_bed(file, key, why)) {
      spdlog::info("bed: {} particles from the cache ({})", bed->set.particles.size(), file.string());
      return std::move(*bed);
    }
    if (!why.empty()) spdlog::warn("bed cache: {}: {}; generating the bed again", file.string(), why);
    const auto t0 = std::chrono::steady_clock::now();
    GeneratedParticles bed = generate_particles_with_report(spec, c);
    const double took = seconds_since(t0);
    if (took >= min_seconds) {
      try {
        write_cached_bed(file, key, bed);
        spdlog::info("bed: generated in {:.1f} s, stored in the cache ({})", took, file.string());
      } catch (const std::exception& e) {
        spdlog::warn("bed cache: {}; the bed is not stored", e.what());
      }
    }
    return bed;
  };
}

}  // namespace gridfree
