// SPDX-License-Identifier: GPL-3.0-or-later
// read_json_file: a JSON document from disk within the limits of
// core/json_limits.h (size, nesting depth, number range); malformed input is
// reported as "file:line:col: what is wrong".
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/json_limits.h"
#include "job/job_spec.h"

namespace gridfree {

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw InputError(file.string(), "is a directory, not a JSON file");
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxJsonBytes)
    throw InputError(file.string(), "larger than " + std::to_string(kMaxJsonBytes >> 20) + " MiB (" +
                                        std::to_string(size) + " bytes)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_json_text(buffer.str(), file.string());
}

}  // namespace gridfree
