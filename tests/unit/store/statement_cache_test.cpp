// SPDX-License-Identifier: GPL-3.0-or-later
// Prepared statements kept for reuse on a connection (store/statement_cache.h):
// a handle comes back reset, with its bindings cleared, and follows schema
// changes; a text in use twice gets two handles; past the cap, statements
// are finalized instead of kept.
#include <gtest/gtest.h>

#include <filesystem>

#include "scratch_dir.h"
#include "store/sqlite.h"

namespace gridfree {
namespace {

class StatementCacheTest : public ::testing::Test {
 protected:
  std::filesystem::path file_ = test_support::fresh_db_path(
      "unit_store", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Database db_{file_, true};

  void SetUp() override { db_.exec("CREATE TABLE t (id INTEGER PRIMARY KEY, v INTEGER NOT NULL)"); }
};

TEST_F(StatementCacheTest, ASecondUseOfATextTakesTheFirstHandleBack) {
  db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(1).run();
  EXPECT_EQ(db_.statements().idle(), 1U);
  {
    auto st = db_.prepare("INSERT INTO t (v) VALUES (?)");
    EXPECT_EQ(db_.statements().idle(), 0U);  // taken, not prepared anew
    st.bind_all(2).run();
  }
  EXPECT_EQ(db_.statements().idle(), 1U);
  EXPECT_EQ(db_.statements().texts(), 1U);
  auto sum = db_.prepare("SELECT SUM(v), COUNT(*) FROM t");
  ASSERT_TRUE(sum.step());
  EXPECT_EQ(sum.as_int(0), 3);
  EXPECT_EQ(sum.as_int(1), 2);
}

TEST_F(StatementCacheTest, AReusedHandleHasNoBindingsLeft) {
  {
    auto st = db_.prepare("SELECT ?");
    st.bind(1, 5LL);
    ASSERT_TRUE(st.step());
    EXPECT_EQ(st.as_int(0), 5);
  }
  auto st = db_.prepare("SELECT ?");
  ASSERT_TRUE(st.step());
  EXPECT_TRUE(st.is_null(0));
}

TEST_F(StatementCacheTest, AHandleLeftMidwayStartsAgainFromTheFirstRow) {
  for (int v = 1; v <= 3; ++v) db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(v).run();
  {
    auto st = db_.prepare("SELECT v FROM t ORDER BY v");
    ASSERT_TRUE(st.step());
    ASSERT_TRUE(st.step());
    EXPECT_EQ(st.as_int(0), 2);
  }
  auto st = db_.prepare("SELECT v FROM t ORDER BY v");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.as_int(0), 1);
}

TEST_F(StatementCacheTest, AHandleLeftMidwayHoldsNoLock) {
  db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(1).run();
  db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(2).run();
  {
    auto st = db_.prepare("SELECT v FROM t");
    ASSERT_TRUE(st.step());
  }
  Database other(file_, false, 200);
  other.exec("BEGIN EXCLUSIVE");  // would wait, then fail, while a read were open
  other.exec("COMMIT");
}

TEST_F(StatementCacheTest, ATextInUseTwiceGetsTwoHandles) {
  {
    auto outer = db_.prepare("SELECT 1");
    auto inner = db_.prepare("SELECT 1");
    ASSERT_TRUE(outer.step());
    ASSERT_TRUE(inner.step());
  }
  EXPECT_EQ(db_.statements().idle(), 2U);
  EXPECT_EQ(db_.statements().texts(), 1U);
}

TEST_F(StatementCacheTest, AKeptHandleFollowsASchemaChange) {
  db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(7).run();
  {
    auto st = db_.prepare("SELECT * FROM t");
    ASSERT_TRUE(st.step());
    EXPECT_EQ(st.as_text(1), "7");
  }
  db_.exec("ALTER TABLE t ADD COLUMN w TEXT NOT NULL DEFAULT 'added'");
  auto st = db_.prepare("SELECT * FROM t");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.as_text(2), "added");
}

TEST_F(StatementCacheTest, AHandleWhoseStepFailedIsUsableAgain) {
  EXPECT_THROW(db_.prepare("INSERT INTO t (v) VALUES (?)").bind(1, std::nullopt).run(), SqliteError);
  db_.prepare("INSERT INTO t (v) VALUES (?)").bind_all(4).run();
  auto st = db_.prepare("SELECT COUNT(*) FROM t");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.as_int(0), 1);
}

TEST_F(StatementCacheTest, AFailedPrepareKeepsNothing) {
  EXPECT_THROW(db_.prepare("SELECT nope FROM t"), SqliteError);
  EXPECT_EQ(db_.statements().idle(), 0U);
}

TEST(StatementCacheCap, TextsPastTheCapAreNotKept) {
  StatementCache cache(2);
  EXPECT_NE(cache.take("SELECT 1").key, nullptr);
  EXPECT_NE(cache.take("SELECT 2").key, nullptr);
  const StatementCache::Taken third = cache.take("SELECT 3");
  EXPECT_EQ(third.key, nullptr);
  EXPECT_EQ(third.statement, nullptr);
  EXPECT_NE(cache.take("SELECT 1").key, nullptr);  // a kept text still is
  EXPECT_EQ(cache.texts(), 2U);
}

}  // namespace
}  // namespace gridfree
