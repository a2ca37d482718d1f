// SPDX-License-Identifier: GPL-3.0-or-later
// Canonical JSON and the job hash (job/job_hash.h).
//
// canonical_json: objects with keys in byte order (nlohmann::json keeps
// them sorted), no whitespace, strings escaped as JSON, every number
// written as a double in shortest round-trip form (std::to_chars), −0 as 0.
// So {"a": 20} and {"a": 20.0} are the same text; any change of value is
// not. Integers beyond 2^53 would collide with neighbours: the schemas keep
// seeds below that.
#include <charconv>
#include <stdexcept>

#include "core/version.h"
#include "job/job_hash.h"
#include "job/job_normalise.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

void append_canonical(const nlohmann::json& j, std::string& out) {
  using value_t = nlohmann::json::value_t;
  switch (j.type()) {
    case value_t::object: {
      out += '{';
      bool first = true;
      for (const auto& [key, value] : j.items()) {
        if (!first) out += ',';
        first = false;
        out += nlohmann::json(key).dump();
        out += ':';
        append_canonical(value, out);
      }
      out += '}';
      break;
    }
    case value_t::array: {
      out += '[';
      for (std::size_t i = 0; i < j.size(); ++i) {
        if (i > 0) out += ',';
        append_canonical(j[i], out);
      }
      out += ']';
      break;
    }
    case value_t::number_integer:
    case value_t::number_unsigned:
    case value_t::number_float: {
      double x = j.get<double>();
      if (x == 0) x = 0;  // −0 → 0
      char buf[32];
      const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
      if (ec != std::errc()) throw std::runtime_error("canonical_json: cannot format a number");
      out.append(buf, end);
      break;
    }
    case value_t::string:
    case value_t::boolean:
    case value_t::null:
      out += j.dump();
      break;
    default:
      throw std::runtime_error("canonical_json: unsupported JSON value");
  }
}

// case.external of an external job, or nullptr.
const nlohmann::json* external_part(const nlohmann::json& job_doc) {
  if (!job_doc.is_object()) return nullptr;
  const auto c = job_doc.find("case");
  if (c == job_doc.end() || !c->is_object()) return nullptr;
  const auto e = c->find("external");
  return e != c->end() && e->is_object() ? &*e : nullptr;
}

}  // namespace

std::string canonical_json(const nlohmann::json& j) {
  std::string out;
  append_canonical(j, out);
  return out;
}

std::string job_hash(const nlohmann::json& job_doc) {
  if (external_part(job_doc) != nullptr) {
    // An external job (docs/INTERFACE.md §2): where the template lies and
    // how the quantities are read are not what the job computes.
    nlohmann::json identity = job_doc;
    auto& e = identity["case"]["external"];
    e.erase("template_dir");
    e.erase("collect");
    return sha256_hex(canonical_json(identity) + "\n" + kSolverVersion);
  }
  // A job that leaves a default out and the same job with the default
  // written (or a preset and its explicit spelling) are one job.
  return sha256_hex(canonical_json(normalised_job(job_doc)) + "\n" + kSolverVersion);
}

std::string job_hash_before_defaults(const nlohmann::json& job_doc) {
  nlohmann::json expanded = job_doc;
  const nlohmann::json* dep = nullptr;
  if (expanded.is_object() && expanded.contains("numerics") && expanded["numerics"].is_object() &&
      expanded["numerics"].contains("deposition"))
    dep = &expanded["numerics"]["deposition"];
  if (dep && dep->is_object()) {
    ProblemList problems;
    const DepositionSpec spec = parse_deposition(*dep, "/numerics/deposition", problems);
    if (problems.empty()) {
      expanded["numerics"]["deposition"] = deposition_json(spec, *dep);
      return sha256_hex(canonical_json(expanded) + "\n" + kSolverVersion);
    }
  }
  return sha256_hex(canonical_json(job_doc) + "\n" + kSolverVersion);
}

}  // namespace gridfree
