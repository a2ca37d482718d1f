// SPDX-License-Identifier: GPL-3.0-or-later
// Generated beds kept on disk for the next job that needs the same bed
// (docs/PARTICLES.md "Bed cache"). The jobs of one case differ in grid and
// numerics only, and a large generated bed (the SSCP-like 93 000-particle
// emulsion: about 16 s) would otherwise be generated again by every one.
//
// A bed is the same when the generator object, the domain, the particle
// diameter and the periodic axes are the same and the worker executable is
// byte for byte the same (its SHA-256 is part of the key, so a rebuilt worker
// never reads a bed an older generator made). Files are
// DIR/<first two hex digits>/<key>.bed, written to a temporary file and
// renamed; a file that is unreadable, truncated or fails its checksum is
// ignored with a warning and replaced. The cache never changes a result: a
// bed read back is the generated one bit for bit. Beds that took less than
// kMinCachedSeconds to generate are not stored.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/case_spec.h"
#include "particles/generators.h"
#include "particles/particle_io.h"

namespace gridfree {

inline constexpr double kMinCachedSeconds = 0.5;

// The SHA-256 (hex) of the running executable (/proc/self/exe); "" if unreadable.
std::string executable_sha256();

// The key of the bed `spec` generates for `case_spec`, built by `program_id`.
std::string bed_cache_key(const GeneratorSpec& spec, const CaseSpec& case_spec, std::string_view program_id);

// DIR/<key[0..2]>/<key>.bed
std::filesystem::path bed_cache_file(const std::filesystem::path& dir, const std::string& key);

// The bed stored in `file` under `key`; nullopt with `why` set when the file
// is missing (why empty), of another key, truncated or corrupt.
std::optional<GeneratedParticles> read_cached_bed(const std::filesystem::path& file, const std::string& key,
                                                  std::string& why);

// Stores `bed` under `key` (temporary file + rename). Throws std::runtime_error
// when the file cannot be written.
void write_cached_bed(const std::filesystem::path& file, const std::string& key, const GeneratedParticles& bed);

// generate_particles_with_report through the cache in `dir`: a stored bed
// when there is one, else generated (and stored when it took at least
// `min_seconds`). Cache problems are warnings, never errors.
BedGenerator cached_bed_generator(std::filesystem::path dir, double min_seconds = kMinCachedSeconds);

}  // namespace gridfree
