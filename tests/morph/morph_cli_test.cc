// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb morph` end to end through the binary: a folder of contour images and a
// sparse-z volume give closed meshes with their statistics; bad input gives one
// error line naming the file and leaves no output behind.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "isovdb/io/mesh_file.h"
#include "isovdb/mesh/validate.h"
#include "morph_test_support.h"
#include "support/test_support.h"

namespace isovdb::morph::test {
namespace {

using isovdb::test::CliRun;
using isovdb::test::expectCleanFailure;
using isovdb::test::TempDir;
using isovdb::test::writeFile;

/// `isovdb morph ARGUMENTS`.
CliRun runMorph(const std::string& arguments) { return isovdb::test::runCli("morph " + arguments); }

TEST(MorphCli, ContourImagesToClosedMeshWithStatisticsAndSlices) {
  TempDir in, out;
  writeStack(in / "slices", vase(), /*asContours=*/true);
  writeFile(in / "h.txt", "0\n8\n16\n");
  const CliRun run =
      runMorph((in / "slices").string() + " --heights " + (in / "h.txt").string() + " -o " +
               (out / "vase.ply").string() + " --method regular --save-slices " + (out / "planes").string() +
               " --stats " + (out / "s.json").string() + " --vdb " + (out / "vase.vdb").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const mesh::MeshReport report = mesh::validateMesh(io::readMesh(out / "vase.ply"), {.selfIntersections = false});
  EXPECT_TRUE(report.closed);
  ASSERT_EQ(report.components, 1);
  EXPECT_EQ(report.componentReports[0].genus, 1);
  EXPECT_TRUE(std::filesystem::exists(out / "vase.vdb"));
  EXPECT_TRUE(std::filesystem::exists(out / "planes" / "plane_0016.png"));
  std::ifstream statsFile(out / "s.json");
  const auto stats = nlohmann::json::parse(statsFile);
  EXPECT_EQ(stats["morph"]["original_slices"], 3);
  EXPECT_EQ(stats["morph"]["intermediate_slices"], 14);
  EXPECT_GT(stats["morph"]["pairs"][0]["iterations"].get<int>(), 0);
}

TEST(MorphCli, SparseVolumeEveryFourthSliceLabelled) {
  TempDir in, out;
  // 64 x 64 x 17 uint8: a pyramid's rectangles on z = 0, 8, 16 only.
  const std::vector<Mask2> masks = pyramid();
  std::string bytes(64 * 64 * 17, '\0');
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 64 * 64; ++i) bytes[(8 * k) * 64 * 64 + i] = masks[k].inside[i] ? 1 : 0;
  writeFile(in / "v.raw", bytes);
  const CliRun run = runMorph((in / "v.raw").string() + " --dims 64,64,17 --type uint8 --slice-step 8 -o " +
                              (out / "p.ply").string() + " --stats " + (out / "s.json").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const mesh::MeshReport report = mesh::validateMesh(io::readMesh(out / "p.ply"), {.selfIntersections = false});
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.components, 1);
  std::ifstream statsFile(out / "s.json");
  EXPECT_EQ(nlohmann::json::parse(statsFile)["morph"]["original_slices"], 3);
}

class MorphCliBadInput : public ::testing::Test {
 protected:
  TempDir in, out;
  std::string outPly() const { return (out / "mesh.ply").string(); }
  void SetUp() override { writeStack(in / "slices", pyramid()); }
  std::string slices() const { return (in / "slices").string(); }
};

TEST_F(MorphCliBadInput, MissingFolder) {
  expectCleanFailure(runMorph((in / "nope").string() + " --spacing 8 -o " + outPly()), {"nope"}, out);
}

TEST_F(MorphCliBadInput, CorruptImage) {
  writeFile(in / "slices" / "slice_3.png", "\x89PNG\r\n\x1a\n broken");
  expectCleanFailure(runMorph(slices() + " --spacing 8 -o " + outPly()), {"slice_3.png", "not a readable PNG or BMP"},
                     out);
}

TEST_F(MorphCliBadInput, HeightsCountMismatch) {
  writeFile(in / "h.txt", "0 8\n");
  expectCleanFailure(runMorph(slices() + " --heights " + (in / "h.txt").string() + " -o " + outPly()),
                     {"h.txt", "2 heights for 3 slice images"}, out);
}

TEST_F(MorphCliBadInput, NonMonotonicHeights) {
  writeFile(in / "h.txt", "0 8 4\n");
  expectCleanFailure(runMorph(slices() + " --heights " + (in / "h.txt").string() + " -o " + outPly()),
                     {"h.txt", "increase strictly"}, out);
}

TEST_F(MorphCliBadInput, EmptySliceSet) {
  std::filesystem::create_directories(in / "empty");
  writeFile(in / "empty" / "readme.txt", "no images here");
  expectCleanFailure(runMorph((in / "empty").string() + " --spacing 8 -o " + outPly()), {"empty", "no slice images"},
                     out);
}

TEST_F(MorphCliBadInput, NoHeightsNorSpacing) {
  expectCleanFailure(runMorph(slices() + " -o " + outPly()), {"--heights", "--spacing"}, out);
}

}  // namespace
}  // namespace isovdb::morph::test
