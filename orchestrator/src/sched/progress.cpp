// SPDX-License-Identifier: GPL-3.0-or-later
// Progress output (see progress.h).
#include "sched/progress.h"

#include <algorithm>
#include <mutex>

#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

#include "sched/study_eta.h"

namespace gridfree {
namespace {

// Formats log messages and hands them to Progress::print_above.
class ProgressSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit ProgressSink(Progress* progress) : progress_(progress) {}

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    spdlog::memory_buf_t buf;
    formatter_->format(msg, buf);
    progress_->print_above(std::string(buf.data(), buf.size()));
  }
  void flush_() override {}

 private:
  Progress* progress_;
};

}  // namespace

Progress::Progress(bool terminal, std::FILE* out) : terminal_(terminal), out_(out) {
  if (!terminal_) return;
  auto logger = spdlog::default_logger();
  saved_sinks_ = logger->sinks();
  auto sink = std::make_shared<ProgressSink>(this);
  sink->set_pattern("[%l] %v");
  logger->sinks() = {sink};
}

Progress::~Progress() {
  finish();
  if (terminal_) spdlog::default_logger()->sinks() = saved_sinks_;
}

void Progress::print_above(const std::string& text) {
  if (line_open_) std::fprintf(out_, "\r\033[K");
  std::fwrite(text.data(), 1, text.size(), out_);
  if (line_open_) std::fprintf(out_, "%s", last_line_.c_str());
  std::fflush(out_);
}

std::string progress_line(const ProgressCounts& c) {
  const int remaining = std::max(0, c.total - c.done - c.failed);
  std::string eta = "?";
  if (c.eta_s)
    eta = hours_minutes(*c.eta_s);
  else if (c.mean_wall_s > 0)
    eta = hours_minutes(c.mean_wall_s * remaining / std::max(1, c.workers));
  return "[" + std::to_string(c.done + c.failed) + "/" + std::to_string(c.total) + "] running " +
         std::to_string(c.running) + ", failed " + std::to_string(c.failed) + ", ETA " + eta;
}

void Progress::job_finished(const std::string& what, const ProgressCounts& c, bool failed) {
  if (!terminal_) {  // "[3/8] running 2, failed 0, ETA 4 min | PC1 …: converged …"
    if (failed) spdlog::warn("{} | {}", progress_line(c), what);
    else spdlog::info("{} | {}", progress_line(c), what);
    return;
  }
  std::fprintf(out_, "\r\033[K%s\n", what.c_str());
  line_open_ = false;
  update(c);
}

void Progress::update(const ProgressCounts& c) {
  if (!terminal_) return;
  last_line_ = progress_line(c);
  std::fprintf(out_, "\r\033[K%s", last_line_.c_str());
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
