// SPDX-License-Identifier: GPL-3.0-or-later
// One report per problem: a validation that runs the schema and then the
// parsers over one document finds some problems twice (the schema and a
// parser both refuse a value) and some only because of another (a string
// where the domain size array belongs: "expected an array", then "the
// domain size must be > 0" for each of its three elements, which do not
// exist). without_follow_ons keeps, in order, the first problem at each
// pointer and drops every problem inside a value reported as unreadable —
// of the wrong type ("expected ...") or missing ("required, but missing").
#pragma once

#include <vector>

#include "core/input_error.h"

namespace gridfree {

std::vector<Problem> without_follow_ons(const std::vector<Problem>& problems);

}  // namespace gridfree
