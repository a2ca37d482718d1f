// SPDX-License-Identifier: GPL-3.0-or-later
// The "pattern" keyword of the schemas, matched in time linear in the string.
//
// std::regex backtracks recursively and overflows the stack on long user
// strings, so patterns are compiled to a sequence of atoms, each with a
// quantifier, and matched by carrying the set of reachable atom positions
// along the string (O(string length x pattern length), no recursion).
//
// Supported subset (anything else is refused when the schema is loaded):
//   ^ and $ as the first / last character (anchors), literal characters,
//   \x escapes of punctuation, ".", character classes [a-z0-9._-] and
//   [^...], each atom optionally followed by ?, * or +.
// Strings are matched byte by byte (the schemas' classes are ASCII).
#pragma once

#include <bitset>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

class SchemaPattern {
 public:
  // The compiled pattern, or nullopt with `why` set when it uses syntax
  // outside the subset above.
  static std::optional<SchemaPattern> compile(std::string_view pattern, std::string* why);

  // ECMA-262 semantics of the JSON Schema "pattern" keyword: the pattern may
  // match anywhere in `s` unless anchored.
  bool matches(std::string_view s) const;

 private:
  struct Atom {
    std::bitset<256> accepts;
    bool optional = false;  // ? or *
    bool repeats = false;   // * or +
  };
  std::vector<Atom> atoms_;
  bool anchored_start_ = false;
  bool anchored_end_ = false;
};

}  // namespace gridfree
