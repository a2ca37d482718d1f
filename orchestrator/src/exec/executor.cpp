// SPDX-License-Identifier: GPL-3.0-or-later
// Shared executor helpers: run directories, the worker command line, exit descriptions.
#include "exec/executor.h"

#include <csignal>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>

#include "exec/worker_progress.h"

namespace gridfree {

std::string describe(const JobExit& e) {
  switch (e.how) {
    case JobExit::How::kExited:
      return "exit " + std::to_string(e.code);
    case JobExit::How::kSignaled: {
      const char* name = sigabbrev_np(e.signal);
      return "killed by signal " + std::to_string(e.signal) + (name != nullptr ? std::string(" (SIG") + name + ")" : "");
    }
    case JobExit::How::kTimedOut:
      return "timed out" + (e.detail.empty() ? "" : ": " + e.detail);
    case JobExit::How::kKilled:
      return "killed (shutdown)";
    case JobExit::How::kLaunchFailed:
      return "could not start the worker: " + e.detail;
    case JobExit::How::kLost:
      return "lost: " + e.detail;
    case JobExit::How::kRefused:
      return "refused by the cluster: " + e.detail;
    case JobExit::How::kVanished:
      return "vanished: " + e.detail;
  }
  return "unknown";
}

std::vector<std::string> worker_command(const std::filesystem::path& worker, const std::filesystem::path& run_dir,
                                        int threads, const std::filesystem::path& bed_cache) {
  std::vector<std::string> argv = {worker.string(), "solve", (run_dir / "job.json").string(), "-o",
                                   (run_dir / "result.json").string(), "--threads",
                                   std::to_string(threads < 1 ? 1 : threads), "--progress",
                                   progress_file(run_dir).string(), "--checkpoint", checkpoint_file(run_dir).string(),
                                   "--resume", checkpoint_file(run_dir).string()};
  if (!bed_cache.empty()) argv.insert(argv.end(), {"--bed-cache", bed_cache.string()});
  return argv;
}

std::filesystem::path bed_cache_dir(const std::filesystem::path& runs_root) { return runs_root / "beds"; }

std::filesystem::path checkpoint_file(const std::filesystem::path& run_dir) { return run_dir / "checkpoint.bin"; }

void remove_checkpoint(const std::filesystem::path& run_dir) {
  std::error_code ec;
  std::filesystem::remove(checkpoint_file(run_dir), ec);
}

std::filesystem::path runs_root_for(const std::filesystem::path& db_file) {
  auto abs = std::filesystem::absolute(db_file);
  return abs.parent_path() / (abs.filename().string() + ".runs");
}

std::filesystem::path run_dir_for(const std::filesystem::path& runs_root, const std::string& job_hash) {
  const auto flat = runs_root / job_hash;
  if (job_hash.size() < 3 || job_hash.find_first_of("/\\.") != std::string::npos) return flat;
  std::error_code ec;
  if (std::filesystem::is_directory(flat, ec)) return flat;
  return runs_root / job_hash.substr(0, 2) / job_hash;
}

std::filesystem::path prepare_run_dir(const std::filesystem::path& runs_root, const std::string& job_hash,
                                      const std::string& job_json) {
  const auto dir = run_dir_for(runs_root, job_hash);
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / "result.json");
  const auto tmp = dir / "job.json.tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << job_json << '\n';
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, dir / "job.json");
  return dir;
}

std::string tail_of_file(const std::filesystem::path& file, int lines) {
  std::ifstream in(file);
  if (!in) return "";
  std::deque<std::string> last;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last.push_back(line);
    if (static_cast<int>(last.size()) > lines) last.pop_front();
  }
  std::string out;
  for (const auto& l : last) out += (out.empty() ? "" : " | ") + l;
  return out.size() > 600 ? out.substr(out.size() - 600) : out;
}

}  // namespace gridfree
