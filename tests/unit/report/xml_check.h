// SPDX-License-Identifier: GPL-3.0-or-later
// A tiny well-formedness check for the XML/SVG (and the XML-like HTML) the
// report writes: every tag closed in order, attributes quoted, no raw '<'
// or stray '&' in text. Not a full XML parser: enough to catch unbalanced
// or unescaped output. Used by the report tests.
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace gridfree::test {

// HTML elements that have no closing tag.
inline bool is_void_html_element(const std::string& name) {
  for (const char* v : {"meta", "br", "hr", "img", "link", "input"}) {
    if (name == v) return true;
  }
  return false;
}

// Returns "" when well formed, otherwise what is wrong and where.
inline std::string xml_problem(const std::string& text, bool html = false) {
  std::vector<std::string> open;
  std::size_t i = 0;
  auto entity_ok = [&](std::size_t at) {
    const std::size_t semi = text.find(';', at);
    if (semi == std::string::npos || semi - at > 8) return false;
    const std::string name = text.substr(at + 1, semi - at - 1);
    if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos") return true;
    return name.size() > 1 && name[0] == '#';
  };
  while (i < text.size()) {
    const char ch = text[i];
    if (ch == '&') {
      if (!entity_ok(i)) return "stray '&' at offset " + std::to_string(i);
      ++i;
      continue;
    }
    if (ch == '>') return "raw '>' in text at offset " + std::to_string(i);
    if (ch != '<') {
      ++i;
      continue;
    }
    if (text.compare(i, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", i);
      if (end == std::string::npos) return "unterminated comment";
      i = end + 3;
      continue;
    }
    if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
      const std::size_t end = text.find('>', i);
      if (end == std::string::npos) return "unterminated declaration";
      i = end + 1;
      continue;
    }
    const bool closing = text.compare(i, 2, "</") == 0;
    std::size_t j = i + (closing ? 2 : 1);
    std::string name;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '-' ||
                               text[j] == ':' || text[j] == '_')) {
      name += text[j++];
    }
    if (name.empty()) return "raw '<' at offset " + std::to_string(i);
    // Attributes: name="value" (quotes required; no raw '<' inside).
    bool self_closing = false;
    for (;;) {
      while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j >= text.size()) return "unterminated tag <" + name;
      if (text[j] == '>') break;
      if (text.compare(j, 2, "/>") == 0) {
        self_closing = true;
        ++j;
        break;
      }
      const std::size_t eq = text.find('=', j);
      if (eq == std::string::npos || (text[eq + 1] != '"' && text[eq + 1] != '\'')) {
        return "unquoted attribute in <" + name + "> at offset " + std::to_string(j);
      }
      const std::size_t close = text.find(text[eq + 1], eq + 2);
      if (close == std::string::npos) return "unterminated attribute in <" + name;
      const std::string value = text.substr(eq + 2, close - eq - 2);
      if (value.find('<') != std::string::npos) return "raw '<' in attribute of <" + name + ">";
      j = close + 1;
    }
    i = j + 1;
    if (closing) {
      if (open.empty() || open.back() != name) {
        return "</" + name + "> closes <" + (open.empty() ? std::string("nothing") : open.back()) + ">";
      }
      open.pop_back();
    } else if (!self_closing && !(html && is_void_html_element(name))) {
      if (name == "style" || name == "script") {
        const std::size_t end = text.find("</" + name, i);
        if (end == std::string::npos) return "unterminated <" + name + ">";
        i = end;  // raw text content; the closing tag is read next
      }
      open.push_back(name);
    }
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  return {};
}

// Occurrences of `needle` in `text`.
inline int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

}  // namespace gridfree::test
