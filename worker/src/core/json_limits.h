// SPDX-License-Identifier: GPL-3.0-or-later
// Parsing JSON text from users within stated limits (docs/LIMITS.md).
//
// Before nlohmann parses anything, one linear pass over the text checks
//   - the size (kMaxJsonBytes),
//   - the nesting depth of arrays and objects (kMaxJsonDepth), so that no
//     later recursive code (dumping, validation, copying) meets a deep tree,
//   - that every number literal fits a double (1e400 or a 400-digit integer
//     is refused, not turned into an internal error or an infinity).
// Each failure, and every syntax error, is an InputError at
// "origin:line:column" with a bounded reason.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gridfree {

inline constexpr std::size_t kMaxJsonDepth = 64;
inline constexpr std::size_t kMaxJsonBytes = std::size_t{64} << 20;  // 64 MiB
inline constexpr std::size_t kMaxReasonLength = 160;  // characters of a parser message kept

// The document in `text`; `origin` names it in messages (a file path, "--job").
nlohmann::json parse_json_text(std::string_view text, const std::string& origin);

// "origin:line:column" of byte offset `offset` of `text` (1-based line and column).
std::string text_position(std::string_view text, std::size_t offset, const std::string& origin);

}  // namespace gridfree
