// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/version.h"

namespace gridfree {

std::string version_string() { return std::string("gridfree ") + project_version() + " (" + source_revision() + ")"; }

std::string program_version_string(const std::string& program) {
  return program + " " + project_version() + " (commit " + source_revision() + ", " + build_type() + " build)";
}

}  // namespace gridfree
