// SPDX-License-Identifier: GPL-3.0-or-later
// remove_stale_temporaries (report/atomic_file.h): what a writer killed with
// kill -9 left behind goes at the next report write; a live writer's
// temporary file and the report's own files stay.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "report/atomic_file.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// The pid of a process that has ended (a child, reaped).
pid_t ended_pid() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  return child;
}

TEST(StaleTemporaries, TheKilledWritersGoTheLiveOnesAndTheReportStay) {
  const fs::path dir = test_support::fresh_scratch_dir("report_unit", "stale_tmp");
  const std::string dead = std::to_string(ended_pid()), live = std::to_string(getpid());
  for (const std::string& name : std::vector<std::string>{".report.html.tmp-" + dead + "-7", ".speed_accuracy.pdf.tmp-" + dead + "-0",
                                 "speed_accuracy.pdf.tmp", "fig1_a.png.tmp", ".report.md.tmp-" + live + "-3",
                                 "report.html", "speed_accuracy.pdf", "grids.csv"})
    std::ofstream(dir / name) << "x";
  remove_stale_temporaries(dir);
  for (const char* gone : {"speed_accuracy.pdf.tmp", "fig1_a.png.tmp"}) EXPECT_FALSE(fs::exists(dir / gone)) << gone;
  EXPECT_FALSE(fs::exists(dir / (".report.html.tmp-" + dead + "-7")));
  EXPECT_FALSE(fs::exists(dir / (".speed_accuracy.pdf.tmp-" + dead + "-0")));
  EXPECT_TRUE(fs::exists(dir / (".report.md.tmp-" + live + "-3")));
  for (const char* kept : {"report.html", "speed_accuracy.pdf", "grids.csv"}) EXPECT_TRUE(fs::exists(dir / kept)) << kept;
}

}  // namespace
}  // namespace gridfree
