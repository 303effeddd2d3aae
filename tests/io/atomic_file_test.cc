// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <stdexcept>

#include "support/test_support.h"

namespace isovdb::io {
namespace {

std::ptrdiff_t entries(const std::filesystem::path& dir) {
  return std::distance(std::filesystem::directory_iterator(dir), {});
}

TEST(AtomicFile, CommitRenamesAndAnAbandonedFileLeavesNothing) {
  test::TempDir dir;
  {
    AtomicFile file(dir / "a.txt");
    file.write("abc");
    file.commit();
  }
  EXPECT_EQ(test::readFile(dir / "a.txt"), "abc");
  {
    AtomicFile file(dir / "b.txt");
    file.write("abc");
  }
  EXPECT_EQ(entries(dir.path()), 1);
}

// A group holds every commit's rename until commitAll(): the outputs appear together,
// a committed file is readable at its temporary meanwhile, and a group that ends
// without commitAll() (an error after the first output) leaves no file at all.
TEST(CommitGroup, RenamesEveryOutputTogetherOrRemovesThemAll) {
  test::TempDir dir;
  {
    CommitGroup group;
    AtomicFile mesh(dir / "m.ply");
    mesh.write("mesh");
    mesh.commit();
    EXPECT_FALSE(std::filesystem::exists(dir / "m.ply"));
    const std::filesystem::path pending = CommitGroup::readablePath(dir / "m.ply");
    EXPECT_NE(pending, dir / "m.ply");
    EXPECT_EQ(test::readFile(pending), "mesh");
    EXPECT_EQ(CommitGroup::readablePath(dir / "other.ply"), dir / "other.ply");
    AtomicFile stats(dir / "s.json");
    stats.write("{}");
    stats.commit();
    EXPECT_THROW(CommitGroup another, std::logic_error);
    group.commitAll();
  }
  EXPECT_EQ(test::readFile(dir / "m.ply"), "mesh");
  EXPECT_EQ(test::readFile(dir / "s.json"), "{}");
  EXPECT_EQ(entries(dir.path()), 2);

  test::TempDir failed;
  {
    CommitGroup group;
    AtomicFile mesh(failed / "m.ply");
    mesh.write("mesh");
    mesh.commit();
    // The statistics' write fails here: the group ends without commitAll().
  }
  EXPECT_EQ(entries(failed.path()), 0);
  // Without a group, a commit renames at once again.
  AtomicFile alone(failed / "a.txt");
  alone.commit();
  EXPECT_TRUE(std::filesystem::exists(failed / "a.txt"));
}

}  // namespace
}  // namespace isovdb::io
