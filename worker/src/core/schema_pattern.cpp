// SPDX-License-Identifier: GPL-3.0-or-later
// Linear-time matching of the schemas' patterns (core/schema_pattern.h).
#include "core/schema_pattern.h"

#include <algorithm>
#include <cctype>

namespace gridfree {
namespace {

bool is_special(char c) { return std::string_view("\\^$.|?*+()[]{}").find(c) != std::string_view::npos; }

// Parses a class body after '['; `i` ends on the closing ']'.
bool parse_class(std::string_view p, std::size_t& i, std::bitset<256>& set, std::string* why) {
  bool negate = false;
  if (i < p.size() && p[i] == '^') {
    negate = true;
    ++i;
  }
  bool first = true;
  while (i < p.size() && (p[i] != ']' || first)) {
    first = false;
    unsigned char lo = static_cast<unsigned char>(p[i]);
    if (p[i] == '\\') {
      if (i + 1 >= p.size() || std::isalnum(static_cast<unsigned char>(p[i + 1]))) {
        *why = "class escapes other than punctuation are not supported";
        return false;
      }
      lo = static_cast<unsigned char>(p[++i]);
    }
    ++i;
    if (i + 1 < p.size() && p[i] == '-' && p[i + 1] != ']') {
      const unsigned char hi = static_cast<unsigned char>(p[i + 1]);
      if (hi < lo || p[i + 1] == '\\') {
        *why = "bad range in a character class";
        return false;
      }
      for (unsigned c = lo; c <= hi; ++c) set.set(c);
      i += 2;
    } else {
      set.set(lo);
    }
  }
  if (i >= p.size()) {
    *why = "unterminated character class";
    return false;
  }
  if (negate) set.flip();
  return true;
}

}  // namespace

std::optional<SchemaPattern> SchemaPattern::compile(std::string_view p, std::string* why) {
  SchemaPattern out;
  std::size_t i = 0;
  if (!p.empty() && p.front() == '^') {
    out.anchored_start_ = true;
    ++i;
  }
  std::size_t end = p.size();
  if (end > i && p[end - 1] == '$' && (end < 2 || p[end - 2] != '\\')) {
    out.anchored_end_ = true;
    --end;
  }
  const std::string_view body = p.substr(0, end);
  while (i < body.size()) {
    Atom atom;
    const char c = body[i];
    if (c == '[') {
      ++i;
      if (!parse_class(body, i, atom.accepts, why)) return std::nullopt;
    } else if (c == '.') {
      atom.accepts.set();
      atom.accepts.reset('\n');
    } else if (c == '\\') {
      if (i + 1 >= body.size() || !is_special(body[i + 1])) {
        *why = "only escapes of punctuation are supported";
        return std::nullopt;
      }
      atom.accepts.set(static_cast<unsigned char>(body[++i]));
    } else if (is_special(c)) {
      *why = std::string("'") + c + "' (groups, alternation, counted repeats, inner anchors) is not supported";
      return std::nullopt;
    } else {
      atom.accepts.set(static_cast<unsigned char>(c));
    }
    ++i;
    if (i < body.size() && (body[i] == '?' || body[i] == '*' || body[i] == '+')) {
      atom.optional = body[i] != '+';
      atom.repeats = body[i] != '?';
      ++i;
    }
    out.atoms_.push_back(atom);
  }
  return out;
}

bool SchemaPattern::matches(std::string_view s) const {
  const std::size_t n = atoms_.size();
  // reach[k]: atoms 0..k-1 have matched the text read so far.
  std::vector<char> reach(n + 1, 0), next(n + 1, 0);
  const auto close = [&](std::vector<char>& r) {  // skip optional atoms
    for (std::size_t k = 0; k < n; ++k)
      if (r[k] && atoms_[k].optional) r[k + 1] = 1;
  };
  reach[0] = 1;
  close(reach);
  if (reach[n] && !anchored_end_) return true;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    std::fill(next.begin(), next.end(), 0);
    if (!anchored_start_) next[0] = 1;  // a match may start at any position
    for (std::size_t k = 0; k < n; ++k) {
      if (!atoms_[k].accepts.test(c)) continue;
      if (reach[k]) next[k + 1] = 1;
      if (atoms_[k].repeats && reach[k + 1]) next[k + 1] = 1;
    }
    close(next);
    reach.swap(next);
    if (reach[n] && !anchored_end_) return true;
  }
  return reach[n] != 0;
}

}  // namespace gridfree
