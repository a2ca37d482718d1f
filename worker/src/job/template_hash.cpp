// SPDX-License-Identifier: GPL-3.0-or-later
#include "job/template_hash.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "job/job_hash.h"

namespace gridfree {
namespace fs = std::filesystem;
namespace {

bool template_path_inside(const fs::path& root, const fs::path& p) {
  const auto [root_end, p_end] = std::mismatch(root.begin(), root.end(), p.begin(), p.end());
  (void)p_end;
  return root_end == root.end();
}

// The file a template entry stands for: itself, or a symlink's target inside
// the folder. Throws for anything the hash (and the driver's copy) refuses.
fs::path template_entry_target(const fs::path& root, const fs::directory_entry& entry) {
  const fs::path& p = entry.path();
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(p, ec);
  if (ec) throw std::runtime_error("template file " + p.string() + ": " + ec.message());
  if (fs::is_symlink(link)) {
    const fs::path target = fs::canonical(p, ec);
    if (ec) throw std::runtime_error("template symlink " + p.string() + ": its target does not exist");
    if (!template_path_inside(root, target))
      throw std::runtime_error("template symlink " + p.string() + " points outside the template folder (to " +
                               target.string() + ")");
    if (fs::is_directory(target))
      throw std::runtime_error("template symlink " + p.string() +
                               " points to a directory; symlinked folders are not supported, copy the folder");
    if (!fs::is_regular_file(target))
      throw std::runtime_error("template symlink " + p.string() + " points to something not a regular file");
    return target;
  }
  if (fs::is_directory(link)) return {};
  if (!fs::is_regular_file(link))
    throw std::runtime_error("template entry " + p.string() + " is not a regular file, folder or symlink");
  return p;
}

// Feeds `file` into `hash` in 64 KiB pieces; its size must stay `size`.
void hash_template_file(Sha256& hash, const fs::path& display, const fs::path& file, std::uintmax_t size) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("template file " + display.string() + " cannot be read");
  std::vector<char> buf(1 << 16);
  std::uintmax_t seen = 0;
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    hash.update(std::string_view(buf.data(), got));
    seen += got;
  }
  if (in.bad()) throw std::runtime_error("template file " + display.string() + " cannot be read");
  if (seen != size) throw std::runtime_error("template file " + display.string() + " changed while it was read");
}

}  // namespace

std::string template_sha256(const fs::path& dir) {
  std::error_code ec;
  const fs::path root = fs::canonical(dir, ec);
  if (ec || !fs::is_directory(root))
    throw std::runtime_error("template folder " + dir.string() + " does not exist or is not a folder");

  std::vector<std::pair<std::string, fs::path>> files;  // relative path, file read
  fs::recursive_directory_iterator it(root, fs::directory_options::none, ec);
  if (ec) throw std::runtime_error("template folder " + dir.string() + ": " + ec.message());
  for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) throw std::runtime_error("template folder " + dir.string() + ": " + ec.message());
    const fs::path target = template_entry_target(root, *it);
    if (target.empty()) continue;
    files.emplace_back(it->path().lexically_relative(root).generic_string(), target);
  }
  if (ec) throw std::runtime_error("template folder " + dir.string() + ": " + ec.message());
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  Sha256 hash;
  for (const auto& [rel, target] : files) {
    std::error_code size_ec;
    const std::uintmax_t size = fs::file_size(target, size_ec);
    if (size_ec) throw std::runtime_error("template file " + (root / rel).string() + " cannot be read");
    const bool executable = (fs::status(target).permissions() & fs::perms::owner_exec) != fs::perms::none;
    std::string header = rel;
    header += '\0';
    header += executable ? "x" : "-";
    header += '\0';
    header += std::to_string(size);
    header += '\0';
    hash.update(header);
    hash_template_file(hash, root / rel, target, size);
  }
  return hash.hex_digest();
}

}  // namespace gridfree
