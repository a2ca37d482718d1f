// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/json_fields.h"

#include <cmath>

#include "core/schema_validation.h"

namespace gridfree {
namespace {

// The value at key, or nullptr (adding a problem when it is required).
const nlohmann::json* find_field(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                 ProblemList& problems, bool required) {
  if (obj.is_object()) {
    if (auto it = obj.find(key); it != obj.end()) return &*it;
  } else if (!obj.is_null()) {
    problems.add(where, "expected an object");
    return nullptr;
  }
  if (required) problems.add(child_pointer(where, key), "required, but missing");
  return nullptr;
}

}  // namespace

std::string child_pointer(const std::string& where, const std::string& key) {
  return where + json_pointer_of({key});
}

std::string child_pointer(const std::string& where, std::size_t index) {
  return where + "/" + std::to_string(index);
}

double read_number(const nlohmann::json& obj, const std::string& key, const std::string& where,
                   ProblemList& problems, std::optional<double> fallback) {
  const nlohmann::json* v = find_field(obj, key, where, problems, !fallback.has_value());
  if (v == nullptr) return fallback.value_or(0.0);
  if (!v->is_number()) {
    problems.add(child_pointer(where, key), "expected a number, got " + v->dump());
    return fallback.value_or(0.0);
  }
  return v->get<double>();
}

std::int64_t read_integer(const nlohmann::json& obj, const std::string& key, const std::string& where,
                          ProblemList& problems, std::optional<std::int64_t> fallback) {
  const nlohmann::json* v = find_field(obj, key, where, problems, !fallback.has_value());
  if (v == nullptr) return fallback.value_or(0);
  if (v->is_number_integer()) return v->get<std::int64_t>();
  if (v->is_number_float()) {
    const double x = v->get<double>();
    if (std::floor(x) == x && std::abs(x) < 9007199254740992.0) return static_cast<std::int64_t>(x);
  }
  problems.add(child_pointer(where, key), "expected an integer, got " + v->dump());
  return fallback.value_or(0);
}

std::uint64_t read_seed(const nlohmann::json& obj, const std::string& key, const std::string& where,
                        ProblemList& problems, std::optional<std::uint64_t> fallback) {
  const nlohmann::json* v = find_field(obj, key, where, problems, !fallback.has_value());
  if (v == nullptr) return fallback.value_or(0);
  if (v->is_number_unsigned() && v->get<std::uint64_t>() < (std::uint64_t(1) << 53)) return v->get<std::uint64_t>();
  if (v->is_number_integer() && v->get<std::int64_t>() >= 0) return static_cast<std::uint64_t>(v->get<std::int64_t>());
  problems.add(child_pointer(where, key), "expected an integer in [0, 2^53), got " + v->dump());
  return fallback.value_or(0);
}

std::string read_string(const nlohmann::json& obj, const std::string& key, const std::string& where,
                        ProblemList& problems, std::optional<std::string> fallback) {
  const nlohmann::json* v = find_field(obj, key, where, problems, !fallback.has_value());
  if (v == nullptr) return fallback.value_or("");
  if (!v->is_string()) {
    problems.add(child_pointer(where, key), "expected a string, got " + v->dump());
    return fallback.value_or("");
  }
  return v->get<std::string>();
}

std::array<double, 3> read_vector3(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                   ProblemList& problems, std::optional<std::array<double, 3>> fallback) {
  const nlohmann::json* v = find_field(obj, key, where, problems, !fallback.has_value());
  const std::array<double, 3> none = fallback.value_or(std::array<double, 3>{});
  if (v == nullptr) return none;
  if (!v->is_array() || v->size() != 3) {
    problems.add(child_pointer(where, key), "expected an array of 3 numbers, got " + v->dump());
    return none;
  }
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(*v)[i].is_number()) {
      problems.add(child_pointer(child_pointer(where, key), i), "expected a number, got " + (*v)[i].dump());
      return none;
    }
    out[i] = (*v)[i].get<double>();
  }
  return out;
}

const nlohmann::json& read_object(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                  ProblemList& problems, bool required) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  const nlohmann::json* v = find_field(obj, key, where, problems, required);
  if (v == nullptr) return kEmpty;
  if (!v->is_object()) {
    problems.add(child_pointer(where, key), "expected an object, got " + v->dump());
    return kEmpty;
  }
  return *v;
}

}  // namespace gridfree
