// SPDX-License-Identifier: GPL-3.0-or-later
// The terminal progress line and log lines never share a line
// (sched/progress.h): a log line written while the progress line is open
// first clears it ("\r\033[K"), then the progress line is drawn again.
#include <cstdio>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "sched/progress.h"

namespace gridfree {
namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int ch = std::fgetc(f); ch != EOF; ch = std::fgetc(f)) out += static_cast<char>(ch);
  return out;
}

TEST(Progress, LogLinesClearAndRedrawTheProgressLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(true, f);
    ProgressCounts c;
    c.total = 10;
    c.done = 3;
    c.running = 2;
    c.eta_s = 3900;
    progress.update(c);
    spdlog::info("series X complete");
  }
  const std::string out = contents(f);
  std::fclose(f);
  const std::string line = "[3/10] running 2, failed 0, ETA 1 h 05 min";
  // drawn, cleared, the log line on its own line, drawn again, ended.
  EXPECT_EQ(out, "\r\033[K" + line + "\r\033[K[info] series X complete\n" + line + "\n");
}

TEST(Progress, WithoutATerminalLogsGoToTheLoggerUntouched) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(false, f);
    ProgressCounts c;
    c.total = 1;
    progress.update(c);
  }
  EXPECT_EQ(contents(f), "");  // no progress line, no escape codes
  std::fclose(f);
}

// Off a terminal a finished job is one log line: the counts, " | ", the job
// and its outcome (the ETA never runs into the job's name); a failure at warn.
TEST(Progress, WithoutATerminalAFinishedJobIsOneLineAndFailuresWarn) {
  std::ostringstream log;
  auto logger = spdlog::default_logger();
  const auto saved = logger->sinks();
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(log);
  sink->set_pattern("[%l] %v");
  logger->sinks() = {sink};
  {
    Progress progress(false, stderr);
    ProgressCounts c;
    c.total = 2;
    c.done = 1;
    c.eta_s = 240;
    progress.job_finished("PC1 Δ*=2: converged", c);
    c.failed = 1;
    progress.job_finished("PC1 Δ*=1: failed: worker crashed", c, true);
  }
  logger->sinks() = saved;
  const std::string text = log.str();
  EXPECT_NE(text.find("[info] [1/2] running 0, failed 0, ETA 4 min | PC1 Δ*=2: converged\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("[warning] [2/2] running 0, failed 1, ETA 4 min | PC1 Δ*=1: failed"), std::string::npos) << text;
}

}  // namespace
}  // namespace gridfree
