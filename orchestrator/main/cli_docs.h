// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree --man-page` / `--bash-completion` (clidoc/doc_request.h): what
// gridfree's man page says beyond its command-line definition.
#pragma once

#include "clidoc/man_page.h"

namespace gridfree::cli {

ManPageInfo gridfree_man_page_info();

}  // namespace gridfree::cli
