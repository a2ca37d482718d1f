// SPDX-License-Identifier: GPL-3.0-or-later
// Waiting for a busy database (store/busy_wait.h).
#include "store/busy_wait.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <thread>

namespace gridfree {
namespace {

// SQLite's unix VFS takes the WAL write lock as a byte-range lock on byte
// 120 of the "-shm" file (WALINDEX_LOCK_OFFSET + WAL_WRITE_LOCK).
constexpr off_t kWalWriteLockByte = 120;

std::string command_line(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::replace(text.begin(), text.end(), '\0', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  if (text.size() > 120) text = text.substr(0, 120) + "...";
  return text;
}

}  // namespace

std::string database_lock_holder(const std::filesystem::path& db_file) {
  const std::string shm = db_file.string() + "-shm";
  const int fd = ::open(shm.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "another process";
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = kWalWriteLockByte;
  lock.l_len = 1;
  const bool found = ::fcntl(fd, F_GETLK, &lock) == 0 && lock.l_type != F_UNLCK && lock.l_pid > 0;
  ::close(fd);
  if (!found) return "another process";
  const std::string cmd = command_line(lock.l_pid);
  return "pid " + std::to_string(lock.l_pid) + (cmd.empty() ? std::string() : " (" + cmd + ")");
}

int busy_wait_handler(void* state, int attempt) {
  auto& w = *static_cast<BusyWait*>(state);
  const auto now = std::chrono::steady_clock::now();
  if (attempt == 0) {
    w.since = now;
    w.announced = false;
  }
  const auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(now - w.since).count();
  if (waited >= w.limit_ms) return 0;
  if (!w.announced && waited >= 2000) {
    std::cerr << "waiting for the database " << w.file.string() << ": it is being written by "
              << database_lock_holder(w.file) << " (up to " << w.limit_ms / 1000 << " s)" << std::endl;
    w.announced = true;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(std::min(100, 1 << std::min(attempt, 7))));
  return 1;
}

}  // namespace gridfree
