// SPDX-License-Identifier: GPL-3.0-or-later
// Whole files for the tests that write their inputs and read outputs: JSON
// documents and raw contents.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

namespace gridfree::test_support {

// `doc` written to `file`, indented.
inline void save_json(const std::filesystem::path& file, const nlohmann::json& doc) {
  std::ofstream(file) << doc.dump(2);
}

// The JSON document in `file` (throws when it is not one).
inline nlohmann::json load_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// The bytes of `file` (empty when it cannot be read).
inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace gridfree::test_support
