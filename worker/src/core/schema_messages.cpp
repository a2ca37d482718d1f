// SPDX-License-Identifier: GPL-3.0-or-later
// Wording of schema problems (core/schema_messages.h).
#include "core/schema_messages.h"

#include <sstream>

namespace gridfree {
namespace {

// Length of the longest prefix of s with at most `max_chars` UTF-8 characters.
std::size_t utf8_prefix(const std::string& s, std::size_t max_chars) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;  // continuation byte
    if (chars == max_chars) return i;
    ++chars;
  }
  return s.size();
}

}  // namespace

std::string schema_type_of(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "boolean";
  if (v.is_number_integer()) return "integer";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  return "object";
}

std::string show_value(const nlohmann::json& v) {
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " item" : " items");
  if (v.is_object()) return "an object with " + std::to_string(v.size()) + (v.size() == 1 ? " key" : " keys");
  if (!v.is_string()) return v.dump();  // numbers, booleans, null: short
  const auto& s = v.get_ref<const std::string&>();
  const std::size_t cut = utf8_prefix(s, kQuotedPrefix);
  std::string out(1, '\'');
  out.append(s, 0, cut);
  if (cut < s.size()) {
    out += "...' (";
    out += std::to_string(s.size());
    out += " bytes)";
  } else {
    out += '\'';
  }
  return out;
}

std::string with_article(const std::string& type) {
  if (type.empty()) return type;
  const bool vowel = std::string("aeiou").find(type[0]) != std::string::npos;
  return (vowel ? "an " : "a ") + type;
}

std::string type_names(const nlohmann::json& type) {
  if (type.is_string()) return type.get<std::string>();
  return join_values(type, " or ");
}

std::string join_values(const nlohmann::json& values, const std::string& separator) {
  std::string out;
  for (const auto& v : values) {
    if (!out.empty()) out += separator;
    out += v.is_string() ? v.get<std::string>() : v.dump();
  }
  return out;
}

std::string show_bound(const nlohmann::json& bound) {
  if (bound.is_number_integer()) return bound.dump();
  std::ostringstream os;
  os << bound.get<double>();
  return os.str();
}

}  // namespace gridfree
