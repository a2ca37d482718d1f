// SPDX-License-Identifier: GPL-3.0-or-later
// The repository speaks of itself only: every document a file names
// (an upper-case `.md` name, or a path under docs/) exists in the source tree, and nothing points
// at a folder outside it (a sibling `shared` folder, this machine's paths).
// The scan walks the source tree as a fresh clone has it (build folders and
// hidden entries other than .ci and .gitignore are skipped) and reads every text file.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "project_paths.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

struct Finding {
  std::string file;
  std::string what;
};

// Patterns are assembled from pieces so this file does not match itself.
const std::string kOutside[] = {std::string("..") + "/shared", std::string("/") + "work/"};

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool upper_name_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

// Every ".md" that ends a word, with the run of characters in `part` before
// it: the names the patterns \b[A-Z][A-Z0-9_]+\.md\b and
// \bdocs/[A-Za-z0-9_]+\.md\b match. A scan, not std::regex: the test reads
// the whole repository, which the regex engine took 40 s for under the
// sanitizers.
template <class Part>
std::vector<std::pair<std::size_t, std::size_t>> md_words(const std::string& text, Part part) {
  std::vector<std::pair<std::size_t, std::size_t>> out;  // [begin, end) of "<run>.md"
  for (std::size_t dot = text.find(".md"); dot != std::string::npos; dot = text.find(".md", dot + 1)) {
    const std::size_t end = dot + 3;
    if (end < text.size() && word_char(text[end])) continue;
    std::size_t begin = dot;
    while (begin > 0 && part(text[begin - 1])) --begin;
    if (begin < dot) out.emplace_back(begin, end);
  }
  return out;
}

// Problems in one file's text, given the names of the .md files that exist.
std::vector<std::string> problems_in(const std::string& text, const std::set<std::string>& md_names,
                                     const fs::path& source_dir) {
  std::vector<std::string> out;
  for (const auto& [begin, end] : md_words(text, upper_name_char)) {
    const bool whole_word = begin == 0 || !word_char(text[begin - 1]);
    const std::string name = text.substr(begin, end - begin);
    if (whole_word && name[0] >= 'A' && name[0] <= 'Z' && name.size() > 4 && md_names.count(name) == 0)
      out.push_back("names " + name + ", which is not in the repository");
  }
  const std::string docs = "docs/";
  for (const auto& [begin, end] : md_words(text, word_char)) {
    if (begin < docs.size() || text.compare(begin - docs.size(), docs.size(), docs) != 0) continue;
    const std::size_t from = begin - docs.size();
    if (from > 0 && word_char(text[from - 1])) continue;
    const std::string path = text.substr(from, end - from);
    if (!fs::is_regular_file(source_dir / path)) out.push_back("names " + path + ", which does not exist");
  }
  for (const auto& s : kOutside)
    if (text.find(s) != std::string::npos) out.push_back("points outside the repository: " + s);
  return out;
}

bool skipped_dir(const fs::path& p) {
  const std::string name = p.filename().string();
  if (name == ".ci") return false;
  return name.empty() || name[0] == '.' || name.rfind("build", 0) == 0 || name.rfind("cmake-build", 0) == 0 ||
         name == "reports" || name == "out";
}

bool is_text(const std::string& s) { return s.find('\0') == std::string::npos; }

std::vector<fs::path> source_files(const fs::path& root) {
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && skipped_dir(it->path())) {
      it.disable_recursion_pending();
      continue;
    }
    const std::string name = it->path().filename().string();
    const bool hidden = name[0] == '.' && name != ".gitignore";  // e.g. a worktree's .git file
    if (it->is_regular_file() && !hidden && it->file_size() < 4'000'000) files.push_back(it->path());
  }
  return files;
}

using gridfree::test_support::kSourceDir;
using gridfree::test_support::slurp;

TEST(DocReferences, ScannerFlagsMissingDocumentsAndOutsidePaths) {
  const std::set<std::string> names = {"PHYSICS.md"};
  EXPECT_TRUE(problems_in("see PHYSICS.md §3 and docs/PHYSICS.md", names, kSourceDir).empty());
  EXPECT_EQ(problems_in("see NOWHERE" + std::string(".md"), names, kSourceDir).size(), 1u);
  EXPECT_EQ(problems_in("see docs/" + std::string("nowhere.md"), names, kSourceDir).size(), 1u);
  EXPECT_EQ(problems_in("read " + kOutside[0] + "/X", names, kSourceDir).size(), 1u);
  // Whole words only, as the patterns' \b: inside a longer word, or with a
  // longer extension, a name is not a reference.
  EXPECT_TRUE(problems_in("xNOWHERE.md, NOWHERE.mdx, mydocs/nowhere.md, A.md", names, kSourceDir).empty());
  const std::string md = ".md";
  EXPECT_EQ(problems_in("(NOWHERE" + md + ") and [docs/nowhere" + md + "](x)", names, kSourceDir).size(), 2u);
}

TEST(DocReferences, EveryNamedDocumentExistsAndNothingPointsOutside) {
  ASSERT_TRUE(fs::is_directory(kSourceDir / "docs")) << kSourceDir;
  const auto files = source_files(kSourceDir);
  std::set<std::string> md_names;
  for (const auto& f : files)
    if (f.extension() == ".md") md_names.insert(f.filename().string());
  ASSERT_GT(md_names.size(), 5u);  // the scan found the docs
  std::vector<Finding> findings;
  for (const auto& f : files) {
    const std::string text = slurp(f);
    if (!is_text(text)) continue;
    for (auto& what : problems_in(text, md_names, kSourceDir))
      findings.push_back({fs::relative(f, kSourceDir).string(), what});
  }
  for (const auto& f : findings) ADD_FAILURE() << f.file << ": " << f.what;
  EXPECT_TRUE(findings.empty());
}

}  // namespace
