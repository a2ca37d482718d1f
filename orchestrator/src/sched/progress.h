// SPDX-License-Identifier: GPL-3.0-or-later
// Progress of a run: on a terminal one updating line
//   [12/40] running 2, failed 1, ETA 1 h 05 min
// (ETA = eta_s when given — the cost model scaled by measured times,
// sched/study_eta.h — else mean wall time of finished jobs × remaining
// jobs / workers);
// otherwise one plain log line per finished job (counts | job: outcome). On a terminal the default
// logger's output is routed through the Progress while it lives: the
// progress line is cleared before every log line and redrawn after it, so
// the two never share a line.
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/sinks/sink.h>

namespace gridfree {

struct ProgressCounts {
  int total = 0, done = 0, running = 0, failed = 0;
  double mean_wall_s = 0;
  int workers = 1;
  std::optional<double> eta_s;
};

std::string progress_line(const ProgressCounts& c);

class Progress {
 public:
  explicit Progress(bool terminal, std::FILE* out = stderr);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  // A log line (already formatted, with its newline): printed above the progress line.
  void print_above(const std::string& text);
  // A job finished: `what` = "PC1 superbee fwhm6 bvk Δ*=1.25: converged dp*=1158.9";
  // off a terminal logged after the counts and " | ", at warn when `failed`.
  void job_finished(const std::string& what, const ProgressCounts& c, bool failed = false);
  void update(const ProgressCounts& c);  // redraw (terminal only)
  void finish();                          // ends the updating line

 private:
  bool terminal_;
  std::FILE* out_;
  bool line_open_ = false;
  std::string last_line_;
  std::vector<spdlog::sink_ptr> saved_sinks_;  // the default logger's, restored at destruction
};

}  // namespace gridfree
