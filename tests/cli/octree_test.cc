// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb octree`: one meta-cell's tree, end to end through the binary.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

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

/// Runs `isovdb COMMAND` on the ball with `arguments` and returns its --stats JSON.
nlohmann::json runOnBall(const TempDir& dir, const std::string& command, const std::string& arguments) {
  std::string output;
  const auto stats = dir / (command + ".json");
  EXPECT_EQ(runCommand(cliPath().string() + " -q " + command + " " + writeBall(dir).string() +
                           " --dims 64,64,64 --type uint8 " + arguments + " --stats " + stats.string(),
                       &output),
            0)
      << output;
  return nlohmann::json::parse(readFile(stats));
}

/// `isovdb octree` on the ball in 32-voxel meta-cells, with the tree settings these
/// tests were written for (uniform down to level 2, no QEF criterion) rather than
/// extract's defaults.
nlohmann::json runOctree(const TempDir& dir, const std::string& arguments) {
  return runOnBall(dir, "octree", "--meta-cell 32 --min-level 2 --qef-tolerance -1 " + arguments);
}

TEST(CliOctree, RegularPutsEverySurfaceLeafAtTheMaximumLevel) {
  TempDir dir;
  const nlohmann::json stats =
      runOctree(dir, "--method regular --index 0,0,0 --wireframe " + (dir / "wire.ply").string());
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
  const nlohmann::json regular = runOctree(dir, "--method regular");
  const nlohmann::json adaptive = runOctree(dir, "--method adaptive --finest-size 1");
  EXPECT_TRUE(adaptive["octree"]["balanced"].get<bool>());
  EXPECT_LT(adaptive["octree"]["surface_leaves"].get<int>(), regular["octree"]["surface_leaves"].get<int>());
}

TEST(CliOctree, MetaCellWithoutSurfaceAndBadMethod) {
  TempDir dir;
  std::string output;
  EXPECT_NE(runCommand(cliPath().string() + " -q octree " + writeBall(dir).string() +
                           " --dims 64,64,64 --type uint8 --method sideways",
                       &output),
            0);
  EXPECT_NE(output.find("sideways"), std::string::npos) << output;
}

// An index beyond the surface's meta-cells is refused by name (near the int range it
// overflowed index * size: UBSan's report in the option walk).
TEST(CliOctree, IndexOutsideTheSurfacesMetaCellsIsRefused) {
  TempDir dir;
  for (const std::string index : {"2,0,0", "-2147483648,-2147483648,-2147483648"}) {
    std::string output;
    EXPECT_EQ(runCommand(cliPath().string() + " -q octree " + writeBall(dir).string() +
                             " --dims 64,64,64 --type uint8 --meta-cell 32 --index " + index,
                         &output),
              2)
        << output;
    EXPECT_NE(output.find("--index: " + index + " lies outside the surface's meta-cells (0..1, 0..1, 0..1"),
              std::string::npos)
        << output;
  }
}

// The inspector shows the tree extract builds: with the same settings (here every
// default) on a volume that fits in one meta-cell, the same leaves.
TEST(CliOctree, SameLeavesAsExtractWithTheSameSettings) {
  TempDir dir;
  for (const std::string method : {"regular", "adaptive"}) {
    SCOPED_TRACE(method);
    const nlohmann::json inspected = runOnBall(dir, "octree", "--method " + method);
    const nlohmann::json extracted =
        runOnBall(dir, "extract", "--method " + method + " -o " + (dir / "ball.ply").string());
    ASSERT_EQ(extracted["meta_cells"]["candidates"].get<int>(), 1);  // the 64^3 ball in one 128-voxel meta-cell
    EXPECT_GT(inspected["octree"]["leaves"].get<std::int64_t>(), 0);
    EXPECT_EQ(inspected["octree"]["leaves"].get<std::int64_t>(), extracted["meta_cells"]["leaves"].get<std::int64_t>());
  }
}

}  // namespace
}  // namespace isovdb::test
