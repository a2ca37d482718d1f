// Progress output (see progress.h).
#include "sched/progress.h"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace gridfree {

std::string progress_line(const ProgressCounts& c) {
  const int remaining = std::max(0, c.total - c.done - c.failed);
  std::string eta = "?";
  if (c.mean_wall_s > 0) {
    const double s = c.mean_wall_s * remaining / std::max(1, c.workers);
    char buf[32];
    if (s < 120)
      std::snprintf(buf, sizeof buf, "%.0f s", s);
    else
      std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    eta = buf;
  }
  return "[" + std::to_string(c.done + c.failed) + "/" + std::to_string(c.total) + "] running " +
         std::to_string(c.running) + ", failed " + std::to_string(c.failed) + ", ETA " + eta;
}

void Progress::job_finished(const std::string& what, const ProgressCounts& c) {
  if (!terminal_) {
    spdlog::info("{} {}", progress_line(c), what);
    return;
  }
  std::fprintf(out_, "\r\033[K%s\n", what.c_str());
  line_open_ = false;
  update(c);
}

void Progress::update(const ProgressCounts& c) {
  if (!terminal_) return;
  std::fprintf(out_, "\r\033[K%s", progress_line(c).c_str());
  std::fflush(out_);
  line_open_ = true;
}

void Progress::finish() {
  if (terminal_ && line_open_) {
    std::fprintf(out_, "\n");
    std::fflush(out_);
    line_open_ = false;
  }
}

}  // namespace gridfree
