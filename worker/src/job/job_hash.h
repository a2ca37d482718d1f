// SPDX-License-Identifier: GPL-3.0-or-later
// Job identity: SHA-256 of the canonical normalised job JSON + the solver
// version.
//
// Normalised (job/job_normalise.h): every default left out written in, and
// numerics.deposition expanded, so a job that omits a default and the same
// job that writes it, or a preset and its explicit spelling, are one job.
// Canonical JSON: object keys sorted, no whitespace, every number written as
// a double in shortest round-trip form (so 20 and 20.0 hash alike).
// An sscp_like generator without "emulsion" is normalised with "emulsion":
// "random" (docs/PARTICLES.md): the default changed from the lattice to the
// random packing, and old hashes must not match new beds.
// An external job (case.external, docs/INTERFACE.md §2) is hashed as
// written without case.external.template_dir (a moved study keeps its
// jobs) and case.external.collect (re-reading the quantities is no new
// job); template_sha256, variables, setup, command and version are in it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gridfree {

std::string sha256_hex(std::string_view data);

// SHA-256 fed in pieces (a template folder's files without holding them all):
// update(a); update(b); hex_digest() == sha256_hex(a + b).
class Sha256 {
 public:
  Sha256();
  void update(std::string_view data);
  std::string hex_digest();  // once; the object is spent afterwards

 private:
  std::array<std::uint32_t, 8> state_;
  std::array<unsigned char, 64> block_{};
  std::size_t block_len_ = 0;
  std::uint64_t total_ = 0;
};
std::string canonical_json(const nlohmann::json& j);
std::string job_hash(const nlohmann::json& job_doc);  // uses kSolverVersion

// The hash before defaults were filled in (databases before schema step
// 11): only numerics.deposition expanded. Kept for the store's
// migration to job_hash (store/schema_job_hashes.cpp), which recognises
// the jobs this solver version hashed that way.
std::string job_hash_before_defaults(const nlohmann::json& job_doc);

}  // namespace gridfree
