// SPDX-License-Identifier: GPL-3.0-or-later
// Text helpers shared by the report writers: escaping for XML/HTML, CSV
// fields (RFC 4180 quoting), Markdown table cells, and number formatting
// that is locale-independent and deterministic (same input, same bytes).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace gridfree {

// Escapes & < > " ' so the text is safe inside XML/HTML content and attributes.
std::string xml_escape(std::string_view text);

// A CSV field: quoted (with "" doubling) when it holds , " CR or LF.
std::string csv_field(std::string_view text);

// A Markdown table cell: | escaped, newlines turned into spaces.
std::string md_cell(std::string_view text);

// printf "%.{digits}g" in the C locale; "nan"/"inf" spelled out.
std::string format_g(double value, int digits = 6);

// Full precision for machine-readable tables (round-trips a double).
std::string format_exact(double value);

// format_g / format_exact of an optional; empty string when absent.
std::string format_g(const std::optional<double>& value, int digits = 6);
std::string format_exact(const std::optional<double>& value);

// value·100 with `digits` significant digits and a % sign, never in exponent
// notation (format_percent_fixed); "" when absent.
std::string format_percent(const std::optional<double>& fraction, int digits = 3);

// "1017.3 ± 1.4": U rounded to two significant digits and the value to the
// same decimal place — format_value_u of extrap/value_format.h, the one
// formatter the console shares (U = 0: "± 0"; no usable U: the value alone
// with `digits` significant digits).
std::string format_with_uncertainty(double value, const std::optional<double>& u, int digits = 6);
// The value part of format_with_uncertainty alone ("1017.3"): rounded to the
// decimal place U supports, without "± U" — for a value U does not belong to
// (f0 printed beside the finest grid's f_1 ± U_1).
std::string format_to_uncertainty_digits(double value, const std::optional<double>& u, int digits = 6);

// A file-name-safe slug: letters, digits, '-' and '_' kept, the rest '_'.
std::string slugify(std::string_view text);

}  // namespace gridfree
