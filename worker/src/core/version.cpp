// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/version.h"

namespace gridfree {

std::string version_string() { return program_version_string("gridfree"); }

std::string program_version_string(const std::string& program) {
  return program + " " + project_version() + " (" + source_revision() + ")";
}

}  // namespace gridfree
