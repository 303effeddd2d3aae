// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb octree`: one meta-cell's tree, end to end through the binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace isovdb::test {
namespace {

/// A 64^3 ball of radius 20 as a uint8 raw file.
std::filesystem::path writeBall(const TempDir& dir) {
  std::string bytes(64 * 64 * 64, '\0');
  for (int z = 0; z < 64; ++z)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        if ((x - 31.5) * (x - 31.5) + (y - 31.5) * (y - 31.5) + (z - 31.5) * (z - 31.5) < 400)
          bytes[(z * 64 + y) * 64 + x] = 1;
  writeFile(dir / "ball.raw", bytes);
  return dir / "ball.raw";
}

nlohmann::json runOctree(const TempDir& dir, const std::string& arguments) {
  std::string output;
  const auto stats = dir / "octree.json";
  EXPECT_EQ(
      runCommand(cliPath().string() + " -q octree " + writeBall(dir).string() +
                     " --dims 64,64,64 --type uint8 --meta-cell-size 32 " + arguments + " --stats " + stats.string(),
                 &output),
      0)
      << output;
  return nlohmann::json::parse(readFile(stats));
}

TEST(CliOctree, RegularPutsEverySurfaceLeafAtTheMaximumLevel) {
  TempDir dir;
  const nlohmann::json stats =
      runOctree(dir, "--construction regular --meta-cell 0,0,0 --wireframe " + (dir / "wire.ply").string());
  const auto& tree = stats["octree"];
  EXPECT_EQ(tree["max_level"].get<int>(), 5);  // 32 = 2^5: 1-voxel cells
  const auto perLevel = tree["surface_leaves_per_level"].get<std::vector<int>>();
  ASSERT_EQ(perLevel.size(), 6u);
  EXPECT_GT(perLevel[5], 100);
  for (int level = 0; level < 5; ++level) EXPECT_EQ(perLevel[level], 0) << level;
  EXPECT_EQ(stats["meta_cells"]["surface_meta_cells"].get<int>(), 8);  // the ball spans 2x2x2 meta-cells
  EXPECT_EQ(readFile(dir / "wire.ply").rfind("ply\n", 0), 0u);
}

TEST(CliOctree, AdaptiveIsBalancedAndCoarser) {
  TempDir dir;
  const nlohmann::json regular = runOctree(dir, "--construction regular");
  const nlohmann::json adaptive = runOctree(dir, "--construction adaptive --finest-size 1");
  EXPECT_TRUE(adaptive["octree"]["balanced"].get<bool>());
  EXPECT_LT(adaptive["octree"]["surface_leaves"].get<int>(), regular["octree"]["surface_leaves"].get<int>());
}

TEST(CliOctree, MetaCellWithoutSurfaceAndBadConstruction) {
  TempDir dir;
  std::string output;
  EXPECT_NE(runCommand(cliPath().string() + " -q octree " + writeBall(dir).string() +
                           " --dims 64,64,64 --type uint8 --construction sideways",
                       &output),
            0);
  EXPECT_NE(output.find("sideways"), std::string::npos) << output;
}

}  // namespace
}  // namespace isovdb::test
