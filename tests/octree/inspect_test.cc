// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/inspect.h.
#include "isovdb/octree/inspect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "support/test_support.h"

namespace isovdb::octree {
namespace {

TEST(Inspect, SummaryAndWireframe) {
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {16, 0, 0}, [](int x, int y, int z) {
    return std::sqrt((x - 24.2) * (x - 24.2) + (y - 8.1) * (y - 8.1) + (z - 7.9) * (z - 7.9)) - 4.0;
  });
  const LinearOctree tree =
      buildOctree(s, {.method = cell::ContourMethod::Adaptive}, {.minDepth = 1, .qefTolerance = -1.0f});
  const OctreeSummary sum = summarizeOctree(tree);
  std::size_t total = 0;
  for (std::size_t n : sum.leavesPerDepth) total += n;
  EXPECT_EQ(total, tree.leafCount());
  EXPECT_GT(sum.surfaceLeaves, 0u);
  EXPECT_LE(sum.minLeafDepth, sum.maxLeafDepth);

  test::TempDir dir;
  for (bool binary : {false, true}) {
    const auto path = dir / (binary ? "leaves_bin.ply" : "leaves.ply");
    writeLeafWireframe(tree, path, {.surfaceLeavesOnly = true, .binary = binary});
    const std::string text = test::readFile(path);
    EXPECT_EQ(text.rfind("ply\n", 0), 0u);
    EXPECT_NE(text.find("element vertex " + std::to_string(8 * sum.surfaceLeaves)), std::string::npos);
    EXPECT_NE(text.find("element edge " + std::to_string(12 * sum.surfaceLeaves)), std::string::npos);
    if (binary) {
      const std::size_t header = text.find("end_header\n") + 11;
      EXPECT_EQ(text.size() - header, sum.surfaceLeaves * (8 * 13 + 12 * 8));
    }
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  }
  EXPECT_THROW(writeLeafWireframe(tree, dir / "missing" / "x.ply"), IoError);
}

}  // namespace
}  // namespace isovdb::octree
