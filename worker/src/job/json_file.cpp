// read_json_file: a JSON document from disk, with malformed input reported
// as "file:line:col: what is wrong" (nlohmann gives a byte offset; the line
// and column are counted here from the text).
#include <fstream>
#include <sstream>

#include "job/job_spec.h"

namespace gridfree {
namespace {

// nlohmann's what(): "[json.exception.parse_error.101] parse error at line 3,
// column 5: syntax error while parsing ..." → the part after "column N: ".
std::string parse_reason(const std::string& what) {
  const auto column = what.find("column ");
  if (column != std::string::npos) {
    const auto colon = what.find(": ", column);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  const auto bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

}  // namespace

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte: 1-based index of the character where parsing failed.
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    const std::size_t column = end - line_start + 1;
    throw InputError(file.string() + ":" + std::to_string(line) + ":" + std::to_string(column),
                     "invalid JSON: " + parse_reason(e.what()));
  }
}

}  // namespace gridfree
