// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_docs.h"

#include "clidoc/doc_request.h"
#include "core/version.h"

namespace gridfree::worker_cli {

ManPageInfo worker_man_page_info() {
  ManPageInfo info;
  info.program = "gridfree-worker";
  info.version = project_version();
  info.description = {
      "gridfree-worker solves one job: the steady gas flow through one frozen particle bed on one grid, with the "
      "particle data deposited by a grid-independent Gaussian filter; it writes the result (pressure drop, "
      "residuals, cost) as JSON. gridfree runs it for every job of a study; it can also be used alone, and "
      "generates or converts particle beds, verifies its own order of accuracy and checks grid alignment.",
  };
  info.exit_codes = exit_code_meanings();
  info.environment = {
      {"OMP_NUM_THREADS", "threads of a solve when --threads is not given; default: every core"},
      {"OMP_WAIT_POLICY, GOMP_SPINCOUNT", "when either is set, idle threads behave as it says; otherwise they sleep "
                                          "rather than spin"},
  };
  info.see_also = {"gridfree(1)", "the documents in share/doc/gridfree (SOLVER.md, INTERFACE.md)"};
  return info;
}

}  // namespace gridfree::worker_cli
