// SPDX-License-Identifier: GPL-3.0-or-later
// Small text helpers shared by the input readers and their messages.
#pragma once

#include <string>
#include <string_view>

namespace gridfree {

// ASCII lower case (file keywords and column names are ASCII).
std::string ascii_lower(std::string_view s);

// x as a stream prints it by default (6 significant digits): numbers in messages.
std::string number_text(double x);

}  // namespace gridfree
