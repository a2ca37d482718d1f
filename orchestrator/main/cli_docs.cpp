// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_docs.h"

#include "clidoc/doc_request.h"
#include "core/version.h"

namespace gridfree::cli {

ManPageInfo gridfree_man_page_info() {
  ManPageInfo info;
  info.program = "gridfree";
  info.version = project_version();
  info.exit_codes = exit_code_meanings();
  info.environment = {
      {"GRIDFREE_WORKER", "the worker executable to run; default: gridfree-worker in the directory of gridfree itself"},
  };
  info.see_also = {"gridfree-worker(1)", "the documents in share/doc/gridfree (INTERFACE.md: every command and field)"};
  return info;
}

}  // namespace gridfree::cli
