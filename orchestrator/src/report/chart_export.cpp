// SPDX-License-Identifier: GPL-3.0-or-later
// Chart export through rsvg-convert (see chart_export.h). The converter is
// spawned directly (no shell), its output goes to a temporary file that is
// renamed into place, so a reader never sees half a PDF.
#include "report/chart_export.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>

extern char** environ;

namespace gridfree {
namespace {

// Runs the converter to its end, or until `stop` says so: then it is killed
// and reaped, and ReportInterrupted thrown.
bool run(const std::vector<std::string>& args, const StopRequested& stop) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // Its own process group, so a stop takes whatever it started with it.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], nullptr, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  if (spawned != 0) return false;
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, stop ? WNOHANG : 0);
    if (r == pid) break;
    if (r < 0) return false;
    if (stop()) {
      ::killpg(pid, SIGKILL);
      waitpid(pid, &status, 0);
      throw ReportInterrupted();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

std::filesystem::path find_svg_converter() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const auto candidate = std::filesystem::path(dir) / "rsvg-convert";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  return {};
}

std::vector<std::string> export_chart(const std::filesystem::path& converter, const std::filesystem::path& svg,
                                      const StopRequested& stop) {
  std::vector<std::string> written;
  for (const char* format : {"pdf", "png"}) {
    auto target = svg;
    target.replace_extension(format);
    const auto tmp = target.parent_path() /
                     ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-0");
    bool ok = false;
    try {
      ok = run({converter.string(), "-f", format, "-o", tmp.string(), svg.string()}, stop);
    } catch (const ReportInterrupted&) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw;
    }
    if (!ok) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      continue;
    }
    std::filesystem::rename(tmp, target);
    written.push_back(target.filename().string());
  }
  return written;
}

}  // namespace gridfree
