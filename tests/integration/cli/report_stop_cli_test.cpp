// SPDX-License-Identifier: GPL-3.0-or-later
// A stop during the report's chart export: SIGINT while the PDF/PNG
// converter runs (a stand-in rsvg-convert on PATH that writes part of its
// output and then sleeps a minute) ends `gridfree run` within seconds with
// exit 130, the converter killed and no temporary file left in the report
// folder (report/report_stop.h).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

// A converter that starts writing its -o file, says so, then takes a minute.
void write_slow_converter(const fs::path& bin_dir, const fs::path& started) {
  fs::create_directories(bin_dir);
  const fs::path exe = bin_dir / "rsvg-convert";
  std::ofstream(exe) << "#!/bin/sh\n"
                        "out=''\n"
                        "while [ $# -gt 0 ]; do case $1 in -o) out=$2; shift 2 ;; *) shift ;; esac; done\n"
                        "printf '%%PDF-partial' > \"$out\"\n"
                        "echo $$ > " << ts::shell_quote(started.string()) << "\n"
                        "sleep 60\n";
  fs::permissions(exe, fs::perms::owner_all);
}

TEST(ReportStopCli, SigintDuringChartExportExitsAtOnceAndLeavesNoTemporaryFile) {
  const fs::path dir = ts::fresh_scratch_dir("cli_test", "report_stop");
  auto doc = ts::quickstart_document();
  doc["name"] = "stopping";
  const fs::path study = dir / "stopping.json";
  std::ofstream(study) << doc.dump(2);
  const fs::path started = dir / "converter.pid";
  write_slow_converter(dir / "bin", started);

  // The environment words ride along with the fake worker's sleep.
  const pid_t pid = ts::spawn_gridfree_in(
      dir, "run stopping.json -j 2 --db g.sqlite",
      "0 PATH=" + ts::shell_quote((dir / "bin").string()) + ":\"$PATH\"");
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(ts::wait_until([&] { return fs::exists(started) && fs::file_size(started) > 0; }, 120))
      << "the converter never started";
  long converter = 0;
  std::ifstream(started) >> converter;
  const auto signalled = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  ASSERT_TRUE(ts::wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 30));
  const double exit_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  // The loop polls every 20–250 ms; 5 s leaves room for a loaded machine.
  EXPECT_LT(exit_s, 5.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_NE(kill(static_cast<pid_t>(converter), 0), 0) << "the converter is still running";
  // Its children went with it (killed processes may take a moment to be reaped).
  EXPECT_TRUE(ts::wait_until([&] { return killpg(static_cast<pid_t>(converter), 0) != 0; }, 5))
      << "the converter's children are still running";
  for (const auto& e : fs::recursive_directory_iterator(dir / "reports"))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

}  // namespace
