// SPDX-License-Identifier: GPL-3.0-or-later
// The CSS every report page inlines (report.html and the series pages):
// screen layout, the print layout (A4, landscape pages for wide tables) and
// the verdict colours.
#pragma once

namespace gridfree {

const char* report_css();

}  // namespace gridfree
