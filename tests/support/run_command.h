// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a shell command or one of the project's executables for the CLI
// tests: exit code, stdout, stderr.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace gridfree::test_support {

struct CommandRun {
  int exit_code = -1;  // -1: could not start, or ended by a signal
  std::string out;     // stdout
  std::string err;     // stderr
};

// `s` as one single-quoted /bin/sh word.
inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// `command` through /bin/sh; stderr goes through `stderr_file` (overwritten).
inline CommandRun run_command(const std::string& command, const std::filesystem::path& stderr_file) {
  CommandRun r;
  const std::string cmd = command + " 2>'" + stderr_file.string() + "'";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) r.out += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(stderr_file);
  r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
  return r;
}

// `command` through /bin/sh with stderr merged into stdout: its exit code
// (-1: could not start, or ended by a signal) and the merged text.
struct MergedRun {
  int code = -1;
  std::string text;
};

inline MergedRun run_merged(const std::string& command) {
  MergedRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) r.text += buf.data();
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// `query` run by the sqlite3 shell on `db`; its output without trailing
// newlines (stderr kept beside the database in sql.txt).
inline std::string sqlite_query(const std::filesystem::path& db, const std::string& query) {
  auto r = run_command("sqlite3 '" + db.string() + "' \"" + query + "\"", db.parent_path() / "sql.txt");
  while (!r.out.empty() && r.out.back() == '\n') r.out.pop_back();
  return r.out;
}

// The integer `query` prints on `db` (sqlite_query); 0 when it prints none
// (no such table yet, the database busy).
inline int sqlite_int(const std::filesystem::path& db, const std::string& query) {
  const auto s = sqlite_query(db, query);
  return s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) ? 0 : std::stoi(s);
}

// The project's executable `name` (in GRIDFREE_BIN_DIR, which every test is
// compiled with) run with `args`; stderr kept in dir/stderr.txt.
inline CommandRun run_executable(const std::string& name, const std::string& args,
                                 const std::filesystem::path& dir) {
  return run_command(std::string(GRIDFREE_BIN_DIR) + "/" + name + " " + args, dir / "stderr.txt");
}

}  // namespace gridfree::test_support
