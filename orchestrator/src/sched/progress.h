// Progress of a run: on a terminal one updating line
//   [12/40] running 2, failed 1, ETA 3.2 min
// (ETA = mean wall time of finished jobs × remaining jobs / workers);
// otherwise one plain log line per finished job.
#pragma once

#include <cstdio>
#include <string>

namespace gridfree {

struct ProgressCounts {
  int total = 0, done = 0, running = 0, failed = 0;
  double mean_wall_s = 0;
  int workers = 1;
};

std::string progress_line(const ProgressCounts& c);

class Progress {
 public:
  explicit Progress(bool terminal, std::FILE* out = stderr) : terminal_(terminal), out_(out) {}
  ~Progress() { finish(); }
  // A job finished: `what` = "PC1 superbee fwhm6 bvk Δ*=1.25: converged dp*=1158.9".
  void job_finished(const std::string& what, const ProgressCounts& c);
  void update(const ProgressCounts& c);  // redraw (terminal only)
  void finish();                          // ends the updating line

 private:
  bool terminal_;
  std::FILE* out_;
  bool line_open_ = false;
};

}  // namespace gridfree
