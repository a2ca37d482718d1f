// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_docs.h"

#include "clidoc/doc_request.h"
#include "core/version.h"

namespace gridfree::cli {

ManPageInfo gridfree_man_page_info() {
  ManPageInfo info;
  info.program = "gridfree";
  info.version = project_version();
  info.description = {
      "gridfree runs grid-convergence studies of CFD-DEM cases: a study file (JSON) names cases, factor levels, a "
      "design and the grids; gridfree expands it into jobs, runs each with gridfree-worker (locally or through "
      "Slurm), keeps every result in one SQLite database, extrapolates each series to the grid-free limit with an "
      "uncertainty for every grid, and writes HTML and Markdown reports.",
      "Example studies are installed in share/gridfree/studies; a study's relative paths are read from its own "
      "folder, and the database (--db, default ./gridfree.sqlite) and reports (reports/STUDY) go to the working "
      "directory.",
  };
  info.exit_codes = exit_code_meanings();
  info.environment = {
      {"GRIDFREE_WORKER", "the worker executable to run; default: gridfree-worker in the directory of gridfree itself"},
  };
  info.see_also = {"gridfree-worker(1)", "the documents in share/doc/gridfree (INTERFACE.md: every command and field)"};
  return info;
}

}  // namespace gridfree::cli
