// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/leafwise_level_set_writer.h"

#include <gtest/gtest.h>

#include <mutex>

#include <openvdb/io/File.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/global_control.h>

#include <string>

#include "generators/shapes.h"
#include "isovdb/errors.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/volume/band_chunks.h"
#include "isovdb/volume/ingest.h"
#include "support/test_support.h"

namespace isovdb::store {
namespace {

using volume::FieldGrid;
using volume::FieldLeaf;
using volume::MaskGrid;
using volume::Volume;
using volume::VolumeKind;

openvdb::FloatGrid::Ptr readRaw(const std::filesystem::path& path, const std::string& name) {
  openvdb::io::File file(path.string());
  file.open();
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  file.close();
  return grid;
}

/// Same tree node for node: every value OpenVDB iterates, tiles at every level
/// included, has the same coordinate, level, value and state, and both trees
/// have the same nodes per level. A tile where the other tree has a leaf, a
/// wrong inside/outside sign or a pruning difference all fail here.
void expectSameTree(const openvdb::FloatGrid& expected, const openvdb::FloatGrid& actual) {
  EXPECT_EQ(expected.background(), actual.background());
  EXPECT_EQ(expected.tree().nodeCount(), actual.tree().nodeCount());
  EXPECT_EQ(expected.tree().leafCount(), actual.tree().leafCount());
  auto a = expected.cbeginValueAll();
  auto b = actual.cbeginValueAll();
  std::int64_t compared = 0;
  for (; a && b; ++a, ++b, ++compared) {
    ASSERT_EQ(a.getCoord(), b.getCoord()) << "value " << compared;
    ASSERT_EQ(a.getDepth(), b.getDepth()) << "at " << a.getCoord();
    ASSERT_EQ(a.isValueOn(), b.isValueOn()) << "at " << a.getCoord();
    ASSERT_EQ(*a, *b) << "at " << a.getCoord() << " depth " << a.getDepth();
  }
  EXPECT_FALSE(a) << "the streamed tree has fewer values";
  EXPECT_FALSE(b) << "the streamed tree has more values";
  EXPECT_GT(compared, 0);
}

/// The band of `mask` written both ways: the in-memory chunked distance field
/// through writeVdb, and the chunks streamed through LeafwiseLevelSetWriter.
void expectStreamedEqualsInMemory(const Volume& mask, int chunk, const std::string& what,
                                  volume::DistanceMethod method = volume::DistanceMethod::Interface) {
  SCOPED_TRACE(what + " (" + std::string(volume::distanceMethodName(method)) + ")");
  test::TempDir dir;
  const volume::DistanceFieldOptions options{.method = method, .halfWidth = 3, .chunkSize = chunk};
  writeVdb(dir / "memory.vdb", volume::distanceField(mask, options), {.gridName = "band"});

  LeafwiseLevelSetWriter writer(dir / "streamed.vdb", 3.f, mask.geometry(), {.gridName = "band", .source = "t"});
  volume::computeBandInChunks(
      volume::maskGrid(mask), options, [&writer](auto&& leaves) { writer.add(std::move(leaves)); }, nullptr);
  const LevelSetFileSummary summary = writer.commit();

  const auto expected = readRaw(dir / "memory.vdb", "band");
  const auto actual = readRaw(dir / "streamed.vdb", "band");
  ASSERT_TRUE(expected && actual);
  expectSameTree(*expected, *actual);
  EXPECT_EQ(actual->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_EQ(actual->transform(), expected->transform());
  EXPECT_EQ(summary.leafCount, static_cast<std::int64_t>(expected->tree().leafCount()));
  EXPECT_EQ(summary.activeVoxels, static_cast<std::int64_t>(expected->activeVoxelCount()));
  // The spill file is gone; only the output is left.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 2u);
}

Volume shapeMask(samples::ShapeKind kind, int size) {
  auto stream = samples::makeShapeStream(kind, {.size = size});
  return volume::ingestMask(*stream, {});
}

/// A box of mask voxels filled as tiles (cheap at any size).
Volume boxMask(const openvdb::CoordBBox& box, volume::Geometry geometry = {}) {
  openvdb::initialize();
  MaskGrid::Ptr grid = MaskGrid::create(false);
  grid->tree().fill(box, true, true);
  return Volume(VolumeKind::Mask, grid, geometry, "box");
}

TEST(LeafwiseLevelSetWriter, WritesTheTreeTheInMemoryPathBuilds) {
  for (samples::ShapeKind kind : samples::allShapes())
    expectStreamedEqualsInMemory(shapeMask(kind, 64), 32, std::string(samples::shapeName(kind)));
  expectStreamedEqualsInMemory(shapeMask(samples::ShapeKind::SaltDome, 64), 32, "salt-dome",
                               volume::DistanceMethod::Tracker);
  // Touching index 0: leaves at negative origins, so the root has two children in x.
  expectStreamedEqualsInMemory(boxMask({{0, 5, 5}, {40, 30, 30}}), 32, "box at the origin");
  // Large enough that whole 128^3 nodes are inside: inside tiles in the upper node.
  expectStreamedEqualsInMemory(boxMask({{120, 121, 122}, {262, 261, 260}}), 128, "box with an inside 128^3 tile");
}

TEST(LeafwiseLevelSetWriter, WritesWorldUnitsLikeWriteVdb) {
  expectStreamedEqualsInMemory(
      boxMask({{2, 2, 2}, {30, 20, 25}}, {.spacing = {0.25, 0.25, 0.25}, .origin = {-3, 1, 7}}), 16,
      "uniform spacing 0.25");
  expectStreamedEqualsInMemory(boxMask({{2, 2, 2}, {30, 20, 25}}, {.spacing = {1, 2, 3}}), 16, "anisotropic spacing");
}

TEST(LeafwiseLevelSetWriter, LeavesWithoutActiveVoxelsBecomeTilesOfTheirSign) {
  // Hand-made leaves: the band of a box, plus two leaves with no active voxel,
  // one deep inside (all -3) and one outside (all +3), as a chunk could hand out.
  openvdb::initialize();
  const Volume mask = boxMask({{0, 0, 0}, {63, 63, 63}});
  const volume::DistanceFieldOptions options{.halfWidth = 3, .chunkSize = 32};
  auto makeLeaves = [&] {
    std::vector<std::unique_ptr<FieldLeaf>> leaves;
    std::mutex adding;  // chunks hand their leaves out from several threads
    volume::computeBandInChunks(
        volume::maskGrid(mask), options,
        [&leaves, &adding](auto&& batch) {
          const std::lock_guard<std::mutex> lock(adding);
          for (auto& leaf : batch) leaves.push_back(std::move(leaf));
        },
        nullptr);
    leaves.push_back(std::make_unique<FieldLeaf>(openvdb::Coord(24, 24, 24), -3.f, false));
    leaves.push_back(std::make_unique<FieldLeaf>(openvdb::Coord(200, 24, 24), 3.f, false));
    return leaves;
  };
  FieldGrid::Ptr expected = FieldGrid::create(3.f);
  for (auto& leaf : makeLeaves()) expected->tree().addLeaf(leaf.release());
  openvdb::tools::signedFloodFill(expected->tree());
  openvdb::tools::pruneLevelSet(expected->tree());
  ASSERT_EQ(expected->tree().probeConstLeaf(openvdb::Coord(24, 24, 24)), nullptr);

  test::TempDir dir;
  LeafwiseLevelSetWriter writer(dir / "s.vdb", 3.f, {}, {.gridName = "band", .source = {}});
  writer.add(makeLeaves());
  writer.commit();
  const auto actual = readRaw(dir / "s.vdb", "band");
  expectSameTree(*expected, *actual);
  EXPECT_EQ(actual->tree().getValue(openvdb::Coord(27, 27, 27)), -3.f);
}

TEST(LeafwiseLevelSetWriter, SameTreeWhateverTheThreadCount) {
  const Volume mask = shapeMask(samples::ShapeKind::SaltDome, 96);
  test::TempDir dir;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    LeafwiseLevelSetWriter writer(dir / (std::to_string(threads) + ".vdb"), 3.f, {},
                                  {.gridName = "band", .source = {}});
    volume::computeBandInChunks(
        volume::maskGrid(mask), {.halfWidth = 3, .chunkSize = 32},
        [&writer](auto&& leaves) { writer.add(std::move(leaves)); }, nullptr);
    writer.commit();
  }
  expectSameTree(*readRaw(dir / "1.vdb", "band"), *readRaw(dir / "2.vdb", "band"));
}

TEST(LeafwiseLevelSetWriter, LeavesNothingBehindWithoutCommit) {
  test::TempDir dir;
  {
    LeafwiseLevelSetWriter writer(dir / "s.vdb", 3.f, {}, {});
    std::vector<std::unique_ptr<FieldLeaf>> leaves;
    leaves.push_back(std::make_unique<FieldLeaf>(openvdb::Coord(0, 0, 0), 1.f, true));
    writer.add(std::move(leaves));
  }  // destroyed as on an exception or an interruption
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(LeafwiseLevelSetWriter, RejectsALeafAddedTwiceAndAnUnwritableFolder) {
  test::TempDir dir;
  LeafwiseLevelSetWriter writer(dir / "s.vdb", 3.f, {}, {});
  for (int i = 0; i < 2; ++i) {
    std::vector<std::unique_ptr<FieldLeaf>> leaves;
    leaves.push_back(std::make_unique<FieldLeaf>(openvdb::Coord(8, 0, 0), 1.f, true));
    writer.add(std::move(leaves));
  }
  EXPECT_THROW(writer.commit(), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "s.vdb"));
  EXPECT_THROW(LeafwiseLevelSetWriter(dir / "missing" / "s.vdb", 3.f, {}, {}), IoError);
}

}  // namespace
}  // namespace isovdb::store
