// The terminal progress line and log lines never share a line
// (sched/progress.h): a log line written while the progress line is open
// first clears it ("\r\033[K"), then the progress line is drawn again.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
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

}  // namespace
}  // namespace gridfree
