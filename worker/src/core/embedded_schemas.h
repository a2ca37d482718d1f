// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON Schemas of schemas/, compiled into the binaries.
#pragma once

#include <string_view>

namespace gridfree {

// Text of schemas/<name>.json (name without ".json", e.g. "job.schema"),
// or an empty view when there is no such schema.
std::string_view embedded_schema(std::string_view name);

}  // namespace gridfree
