// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree-worker --man-page` / `--bash-completion` (clidoc/doc_request.h):
// what the worker's man page says beyond its command-line definition.
#pragma once

#include "clidoc/man_page.h"

namespace gridfree::worker_cli {

ManPageInfo worker_man_page_info();

}  // namespace gridfree::worker_cli
