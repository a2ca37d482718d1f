// The repository speaks of itself only: every document a file names
// (an upper-case `.md` name, or a path under docs/) exists in the source tree, and nothing points
// at a folder outside it (a sibling `shared` folder, this machine's paths).
// The scan walks the source tree as a fresh clone has it (build folders and
// hidden entries other than .ci and .gitignore are skipped) and reads every text file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
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

// Problems in one file's text, given the names of the .md files that exist.
std::vector<std::string> problems_in(const std::string& text, const std::set<std::string>& md_names,
                                     const fs::path& source_dir) {
  std::vector<std::string> out;
  static const std::regex upper_doc(R"(\b[A-Z][A-Z0-9_]+\.md\b)");
  for (std::sregex_iterator it(text.begin(), text.end(), upper_doc), end; it != end; ++it)
    if (md_names.count(it->str()) == 0) out.push_back("names " + it->str() + ", which is not in the repository");
  static const std::regex docs_path(R"(\bdocs/[A-Za-z0-9_]+\.md\b)");
  for (std::sregex_iterator it(text.begin(), text.end(), docs_path), end; it != end; ++it)
    if (!fs::is_regular_file(source_dir / it->str())) out.push_back("names " + it->str() + ", which does not exist");
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
