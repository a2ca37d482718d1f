// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/render.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace gridfree {
namespace {

bool placeholder_start_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool placeholder_char(char c) { return placeholder_start_char(c) || (c >= '0' && c <= '9'); }

// The name of a placeholder starting at text[at] ("@@"), if one does.
std::optional<std::string_view> placeholder_at(std::string_view text, std::size_t at) {
  if (text.compare(at, 2, "@@") != 0) return std::nullopt;
  std::size_t end = at + 2;
  if (end >= text.size() || !placeholder_start_char(text[end])) return std::nullopt;
  while (end < text.size() && placeholder_char(text[end])) ++end;
  if (text.compare(end, 2, "@@") != 0) return std::nullopt;
  return text.substr(at + 2, end - at - 2);
}

}  // namespace

UndefinedPlaceholder::UndefinedPlaceholder(std::string file_, int line_, std::string name_)
    : std::runtime_error(file_ + ":" + std::to_string(line_) + ": @@" + name_ + "@@ is not a variable"),
      file(std::move(file_)),
      line(line_),
      name(std::move(name_)) {}

std::string render_number(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15) return std::to_string(static_cast<long long>(v));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string render_placeholders(std::string_view text, const RenderVariables& vars, const std::string& file) {
  RenderTexts texts;
  for (const auto& [name, value] : vars) texts.emplace_back(name, render_number(value));
  return render_placeholders(text, texts, file);
}

std::string render_placeholders(std::string_view text, const RenderTexts& vars, const std::string& file) {
  std::string out;
  out.reserve(text.size());
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '\n') ++line;
    const auto name = text[i] == '@' ? placeholder_at(text, i) : std::nullopt;
    if (!name) {
      out += text[i++];
      continue;
    }
    const auto it = std::find_if(vars.begin(), vars.end(), [&](const auto& v) { return v.first == *name; });
    if (it == vars.end()) throw UndefinedPlaceholder(file, line, std::string(*name));
    out += it->second;
    i += name->size() + 4;
  }
  return out;
}

std::vector<std::string> placeholder_names(std::string_view text) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (const auto name = placeholder_at(text, i)) {
      names.emplace_back(*name);
      i += name->size() + 3;
    }
  return names;
}

}  // namespace gridfree
