// SPDX-License-Identifier: GPL-3.0-or-later
// Limits on JSON text from users (core/json_limits.h).
#include "core/json_limits.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "core/input_error.h"

namespace gridfree {
namespace {

bool starts_number(char c) { return c == '-' || (c >= '0' && c <= '9'); }
bool in_number(char c) { return starts_number(c) || c == '+' || c == '.' || c == 'e' || c == 'E'; }

// First problem of the size / depth / number limits, with its byte offset.
struct Violation {
  std::size_t offset = 0;
  std::string reason;
};

std::optional<Violation> scan(std::string_view text) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        return Violation{i, "nested deeper than " + std::to_string(kMaxJsonDepth) + " arrays/objects"};
    } else if (c == ']' || c == '}') {
      if (depth > 0) --depth;  // unbalanced brackets are the parser's to report
    } else if (starts_number(c)) {
      std::size_t end = i;
      while (end < text.size() && in_number(text[end])) ++end;
      const std::string literal(text.substr(i, end - i));
      errno = 0;
      const double x = std::strtod(literal.c_str(), nullptr);
      if (errno == ERANGE && std::isinf(x)) {
        std::string shown = literal.substr(0, 24);
        if (shown.size() < literal.size()) shown += "... (" + std::to_string(literal.size()) + " characters)";
        return Violation{i, "number " + shown + " is out of the range of a double (about 1.8e308)"};
      }
      i = end - 1;
    }
  }
  return std::nullopt;
}

// `s` with control characters and bytes that are not part of a well-formed
// UTF-8 sequence replaced by '?', so a message never carries them to a terminal.
std::string printable(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool ok = len > 0 && i + len <= s.size();
    for (std::size_t k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
    if (!ok || (len == 1 && (c < 0x20 || c == 0x7F))) {
      out += '?';
      ++i;
    } else {
      out.append(s, i, len);
      i += len;
    }
  }
  return out;
}

// nlohmann's what(): "[json.exception.parse_error.101] parse error at line 3,
// column 5: syntax error while parsing ..." -> the part after "column N: ".
std::string parse_reason(const std::string& what) {
  std::string reason = what;
  if (const auto column = what.find("column "); column != std::string::npos) {
    if (const auto colon = what.find(": ", column); colon != std::string::npos) reason = what.substr(colon + 2);
  } else if (const auto bracket = what.find("] "); bracket != std::string::npos) {
    reason = what.substr(bracket + 2);
  }
  if (reason.size() > kMaxReasonLength) reason = reason.substr(0, kMaxReasonLength) + "...";
  return printable(reason);
}

}  // namespace

std::string text_position(std::string_view text, std::size_t offset, const std::string& origin) {
  const std::size_t end = std::min(offset, text.size());
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return origin + ":" + std::to_string(line) + ":" + std::to_string(end - line_start + 1);
}

nlohmann::json parse_json_text(std::string_view text, const std::string& origin) {
  if (text.size() > kMaxJsonBytes)
    throw InputError(origin, "larger than " + std::to_string(kMaxJsonBytes >> 20) + " MiB (" +
                                 std::to_string(text.size()) + " bytes)");
  if (const auto v = scan(text)) throw InputError(text_position(text, v->offset, origin), v->reason);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte: 1-based index of the character where parsing failed.
    throw InputError(text_position(text, e.byte > 0 ? e.byte - 1 : 0, origin),
                     "invalid JSON: " + parse_reason(e.what()));
  } catch (const nlohmann::json::exception& e) {  // anything the scan did not foresee
    throw InputError(origin, "invalid JSON: " + parse_reason(e.what()));
  }
}

}  // namespace gridfree
