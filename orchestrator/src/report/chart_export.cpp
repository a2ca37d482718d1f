// Chart export through rsvg-convert (see chart_export.h). The converter is
// spawned directly (no shell), its output goes to a temporary file that is
// renamed into place, so a reader never sees half a PDF.
#include "report/chart_export.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <sstream>

extern char** environ;

namespace gridfree {
namespace {

bool run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
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

std::vector<std::string> export_chart(const std::filesystem::path& converter, const std::filesystem::path& svg) {
  std::vector<std::string> written;
  for (const char* format : {"pdf", "png"}) {
    auto target = svg;
    target.replace_extension(format);
    const auto tmp = target.string() + ".tmp";
    if (!run({converter.string(), "-f", format, "-o", tmp, svg.string()})) {
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
