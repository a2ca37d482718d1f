// SPDX-License-Identifier: GPL-3.0-or-later
// Reading typed fields out of JSON objects while collecting problems.
//
// Each reader looks up `key` in `obj` (the object found at JSON pointer
// `where`); a missing required field or a wrong type adds a Problem at
// "<where>/<key>" and returns the fallback, so parsing continues and every
// problem is reported at once. Documents are normally schema-validated
// first; these checks keep the parsers safe when they are not.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

std::string child_pointer(const std::string& where, const std::string& key);
std::string child_pointer(const std::string& where, std::size_t index);

// nullopt fallback = required.
double read_number(const nlohmann::json& obj, const std::string& key, const std::string& where,
                   ProblemList& problems, std::optional<double> fallback = std::nullopt);
std::int64_t read_integer(const nlohmann::json& obj, const std::string& key, const std::string& where,
                          ProblemList& problems, std::optional<std::int64_t> fallback = std::nullopt);
// A non-negative integer below 2^53 (exactly representable; see job_hash.h).
std::uint64_t read_seed(const nlohmann::json& obj, const std::string& key, const std::string& where,
                        ProblemList& problems, std::optional<std::uint64_t> fallback = std::nullopt);
std::string read_string(const nlohmann::json& obj, const std::string& key, const std::string& where,
                        ProblemList& problems, std::optional<std::string> fallback = std::nullopt);
std::array<double, 3> read_vector3(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                   ProblemList& problems,
                                   std::optional<std::array<double, 3>> fallback = std::nullopt);
// The object at key (an empty object when absent and optional).
const nlohmann::json& read_object(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                  ProblemList& problems, bool required = false);

}  // namespace gridfree
