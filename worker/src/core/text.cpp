// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/text.h"

#include <cctype>
#include <sstream>

namespace gridfree {

std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string number_text(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

}  // namespace gridfree
