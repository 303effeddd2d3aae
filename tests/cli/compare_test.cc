// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb compare` on the meshes `extract --max-error` is checked with: the figures,
// and exit status 1 when the distance exceeds --max-distance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace isovdb::test {
namespace {

/// A 40^3 NRRD ball of radius 13 (uint8 mask).
std::filesystem::path writeBall(const TempDir& dir) {
  std::string bytes = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 40 40 40\nencoding: raw\n\n";
  for (int z = 0; z < 40; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        const double dx = x - 19.6, dy = y - 20.2, dz = z - 19.7;
        bytes.push_back(static_cast<char>(std::sqrt(dx * dx + dy * dy + dz * dz) < 13.0 ? 1 : 0));
      }
  const auto path = dir / "ball.nrrd";
  writeFile(path, bytes);
  return path;
}

int run(const std::string& arguments, std::string* output) {
  return runCommand(cliPath().string() + " -q " + arguments, output);
}

TEST(CliCompare, MeasuresTheErrorBoundAndFailsBeyondMaxDistance) {
  const TempDir dir;
  const auto ball = writeBall(dir).string();
  const auto regular = (dir / "regular.ply").string(), adaptive = (dir / "adaptive.ply").string();
  std::string output;
  ASSERT_EQ(run("extract " + ball + " --method regular --topology mdmc -o " + regular, &output), 0) << output;
  ASSERT_EQ(run("extract " + ball + " --method adaptive --max-error 0.5 -o " + adaptive, &output), 0) << output;

  const auto stats = (dir / "distance.json").string();
  ASSERT_EQ(run("compare " + regular + " " + adaptive + " --max-distance 0.5 --stats " + stats, &output), 0) << output;
  EXPECT_NE(output.find("distance.hausdorff"), std::string::npos) << output;
  const auto figures = nlohmann::json::parse(readFile(stats))["distance"];
  const double hausdorff = figures["hausdorff"];
  EXPECT_GT(hausdorff, 0.0);
  EXPECT_LE(hausdorff, 0.5);
  EXPECT_LE(figures["a_to_b"]["p99"].get<double>(), figures["a_to_b"]["max"].get<double>());
  EXPECT_GT(figures["b_to_a"]["samples"].get<int>(), 0);

  // The same meshes against a bound they do not meet, and a missing file.
  EXPECT_EQ(run("compare " + regular + " " + adaptive + " --max-distance 0.001", &output), 1) << output;
  EXPECT_NE(run("compare " + regular + " " + (dir / "missing.ply").string(), &output), 0);
  EXPECT_NE(output.find("missing.ply"), std::string::npos) << output;
}

TEST(CliCompare, TheSummaryPromisesTheBoundOnlyWhereOneVoxelCellsCanKeepIt) {
  const TempDir dir;
  const auto ball = writeBall(dir).string();
  const auto stats = (dir / "stats.json").string();
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " extract " + ball + " --method adaptive -o " + (dir / "a.ply").string() +
                           " --stats " + stats,
                       &output),
            0)
      << output;
  EXPECT_NE(output.find("within 1.0 voxel (--max-error)"), std::string::npos) << output;
  EXPECT_EQ(nlohmann::json::parse(readFile(stats))["contour"]["finest_cell_voxels"], 1);
  ASSERT_EQ(runCommand(cliPath().string() + " extract " + ball + " --method adaptive --finest-size 2 -o " +
                           (dir / "b.ply").string() + " --stats " + stats,
                       &output),
            0)
      << output;
  EXPECT_EQ(output.find("within 1.0 voxel"), std::string::npos) << output;
  EXPECT_NE(output.find("cells stop at 2 voxels: not guaranteed"), std::string::npos) << output;
  EXPECT_EQ(nlohmann::json::parse(readFile(stats))["contour"]["finest_cell_voxels"], 2);
}

}  // namespace
}  // namespace isovdb::test
