// SPDX-License-Identifier: GPL-3.0-or-later
// Escaping and number formatting for the report (see text_format.h).
#include "report/text_format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "extrap/value_format.h"

namespace gridfree {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
  return out;
}

std::string md_cell(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    if (ch == '|') {
      out += "\\|";
    } else if (ch == '\n' || ch == '\r') {
      out += ' ';
    } else {
      out += ch;
    }
  }
  return out;
}

namespace {

std::string printf_g(double value, int digits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  std::string out = buffer;
  // snprintf honours LC_NUMERIC; the report is always written with a '.'.
  for (char& ch : out) {
    if (ch == ',') ch = '.';
  }
  if (out == "-0") out = "0";
  return out;
}

}  // namespace

std::string format_g(double value, int digits) { return printf_g(value, digits); }

std::string format_exact(double value) {
  // Shortest of 15..17 significant digits that reads back as the same double.
  for (int digits = 15; digits < 17; ++digits) {
    const std::string text = printf_g(value, digits);
    if (std::strtod(text.c_str(), nullptr) == value) return text;
  }
  return printf_g(value, 17);
}

std::string format_g(const std::optional<double>& value, int digits) {
  return value ? format_g(*value, digits) : std::string();
}

std::string format_exact(const std::optional<double>& value) {
  return value ? format_exact(*value) : std::string();
}

std::string format_percent(const std::optional<double>& fraction, int digits) {
  if (!fraction) return {};
  return format_percent_fixed(*fraction, digits);
}

std::string slugify(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    out += (std::isalnum(c) || ch == '-' || ch == '_') ? ch : '_';
  }
  return out;
}

std::string format_with_uncertainty(double value, const std::optional<double>& u, int digits) {
  return format_value_u(value, u, digits);
}

std::string format_to_uncertainty_digits(double value, const std::optional<double>& u, int digits) {
  return format_value_for_u(value, u, digits);
}

}  // namespace gridfree
