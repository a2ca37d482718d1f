// SPDX-License-Identifier: GPL-3.0-or-later
// @@name@@ placeholders in an external template's files (docs/EXTERNAL.md
// "Rendering"). A placeholder is @@, a name ([A-Za-z_][A-Za-z0-9_]*), @@; any
// other @@ is left as it is. Pure functions.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gridfree {

using RenderVariables = std::vector<std::pair<std::string, double>>;
// Placeholder name → the text written in its place (a number already
// rendered by render_number, or a factor level verbatim).
using RenderTexts = std::vector<std::pair<std::string, std::string>>;

// A placeholder without a variable: where it is and its name.
struct UndefinedPlaceholder : std::runtime_error {
  UndefinedPlaceholder(std::string file_, int line_, std::string name_);
  std::string file;
  int line;
  std::string name;
};

// The value as written into a file: integers as integers ("40", "-3"),
// anything else in shortest round-trip form ("0.0025", "1e-05").
std::string render_number(double v);

// `text` with every placeholder replaced; throws UndefinedPlaceholder
// naming `file`, the 1-based line and the name of the first unknown one.
std::string render_placeholders(std::string_view text, const RenderVariables& vars, const std::string& file);
std::string render_placeholders(std::string_view text, const RenderTexts& texts, const std::string& file);

// The names of the placeholders in `text`, in order of appearance (with repeats).
std::vector<std::string> placeholder_names(std::string_view text);

}  // namespace gridfree
