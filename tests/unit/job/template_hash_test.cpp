// SPDX-License-Identifier: GPL-3.0-or-later
// template_sha256: the recipe (pinned against an independent computation),
// what changes it (contents, x-bit, a rename), what does not (a copy
// elsewhere, an empty folder), and what it refuses (symlinks leaving the
// folder, dangling ones, symlinked folders), each error naming the path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "job/job_hash.h"
#include "job/template_hash.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

void put_template_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

fs::path small_template(const std::string& name) {
  const auto dir = test_support::fresh_scratch_dir("template_hash", name);
  put_template_file(dir / "system" / "controlDict", "endTime @@T@@;\n");
  put_template_file(dir / "Allrun", "#!/bin/sh\necho run\n");
  fs::permissions(dir / "Allrun", fs::perms::owner_exec, fs::perm_options::add);
  put_template_file(dir / "0" / "U", "internalField uniform (0 0 0);\n");
  return dir;
}

std::string template_error(const fs::path& dir) {
  try {
    (void)template_sha256(dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The recipe spelled out by hand: files sorted by relative path, each
// relpath \0 x|- \0 size \0 contents ("0/U" < "Allrun" < "system/..." in byte order).
TEST(TemplateHash, FollowsTheDocumentedRecipe) {
  const auto dir = small_template("recipe");
  using namespace std::string_literals;
  const std::string message = "0/U\0-\0"s + "31\0"s + "internalField uniform (0 0 0);\n" +
                              "Allrun\0x\0"s + "19\0"s + "#!/bin/sh\necho run\n" +
                              "system/controlDict\0-\0"s + "15\0"s + "endTime @@T@@;\n";
  EXPECT_EQ(template_sha256(dir), sha256_hex(message));
  // Independently (Python: hashlib.sha256 over the same bytes).
  EXPECT_EQ(template_sha256(dir), "1e434186b7bc5b04da95f0f59673c31a01385d4619116c5bb1a7924dae8893cf");
}

TEST(TemplateHash, StableAcrossCopiesAndEmptyFolders) {
  const auto a = small_template("copy_a");
  const auto b = test_support::fresh_scratch_dir("template_hash", "copy_b");
  fs::copy(a, b, fs::copy_options::recursive);
  fs::create_directories(b / "constant");  // an empty folder adds nothing
  EXPECT_EQ(template_sha256(a), template_sha256(b));
  EXPECT_EQ(template_sha256(a), template_sha256(a));
}

TEST(TemplateHash, ChangesOnContentEdit) {
  const auto dir = small_template("edit");
  const auto before = template_sha256(dir);
  put_template_file(dir / "system" / "controlDict", "endTime @@T@@; \n");
  EXPECT_NE(template_sha256(dir), before);
}

TEST(TemplateHash, ChangesOnExecutableBit) {
  const auto dir = small_template("xbit");
  const auto before = template_sha256(dir);
  fs::permissions(dir / "Allrun", fs::perms::owner_exec, fs::perm_options::remove);
  EXPECT_NE(template_sha256(dir), before);
  fs::permissions(dir / "Allrun", fs::perms::owner_exec, fs::perm_options::add);
  EXPECT_EQ(template_sha256(dir), before);
}

TEST(TemplateHash, ChangesOnRenameAndOnMove) {
  const auto dir = small_template("rename");
  const auto before = template_sha256(dir);
  fs::rename(dir / "0" / "U", dir / "0" / "V");
  const auto renamed = template_sha256(dir);
  EXPECT_NE(renamed, before);
  fs::create_directories(dir / "1");
  fs::rename(dir / "0" / "V", dir / "1" / "V");
  EXPECT_NE(template_sha256(dir), renamed);
}

TEST(TemplateHash, ChangesWhenAFileIsAdded) {
  const auto dir = small_template("added");
  const auto before = template_sha256(dir);
  put_template_file(dir / "constant" / "empty", "");
  EXPECT_NE(template_sha256(dir), before);
}

TEST(TemplateHash, SymlinkToAFileInsideCountsAsItsContents) {
  const auto dir = small_template("inner_link");
  const auto copy = test_support::fresh_scratch_dir("template_hash", "inner_link_copy");
  fs::copy(dir, copy, fs::copy_options::recursive);
  fs::create_symlink("../0/U", dir / "system" / "U.orig");
  put_template_file(copy / "system" / "U.orig", "internalField uniform (0 0 0);\n");
  EXPECT_EQ(template_sha256(dir), template_sha256(copy));
}

TEST(TemplateHash, RefusesASymlinkLeavingTheFolder) {
  const auto dir = small_template("outer_link");
  const auto outside = test_support::fresh_scratch_dir("template_hash", "outside");
  put_template_file(outside / "secret", "x");
  fs::create_symlink(outside / "secret", dir / "system" / "escape");
  const auto message = template_error(dir);
  EXPECT_NE(message.find((dir / "system" / "escape").string()), std::string::npos) << message;
  EXPECT_NE(message.find("outside the template folder"), std::string::npos) << message;
}

TEST(TemplateHash, RefusesARelativeSymlinkClimbingOut) {
  const auto dir = small_template("climb_link");
  fs::create_symlink("../../climb_link/../outside_again", dir / "system" / "up");
  put_template_file(dir.parent_path() / "outside_again", "y");
  const auto message = template_error(dir);
  EXPECT_NE(message.find("system/up"), std::string::npos) << message;
  EXPECT_NE(message.find("outside the template folder"), std::string::npos) << message;
}

TEST(TemplateHash, RefusesDanglingSymlinksAndSymlinkedFolders) {
  const auto dir = small_template("dangling");
  fs::create_symlink("no_such_file", dir / "broken");
  auto message = template_error(dir);
  EXPECT_NE(message.find((dir / "broken").string()), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;

  const auto dir2 = small_template("dir_link");
  fs::create_directory_symlink("0", dir2 / "zero");
  message = template_error(dir2);
  EXPECT_NE(message.find((dir2 / "zero").string()), std::string::npos) << message;
  EXPECT_NE(message.find("directory"), std::string::npos) << message;
}

TEST(TemplateHash, RefusesAMissingFolderNamingIt) {
  const auto dir = test_support::scratch_root("template_hash") / "no_such_template";
  const auto message = template_error(dir);
  EXPECT_NE(message.find(dir.string()), std::string::npos) << message;
}

}  // namespace
}  // namespace gridfree
