#include "core/version.h"

namespace gridfree {

std::string version_string() {
  return std::string("gridfree ") + project_version() + " (" + source_revision() + ")";
}

}  // namespace gridfree
