// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/meta_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "support/vector_slice_stream.h"

namespace isovdb::volume {
namespace {

using test::VectorSliceStream;

/// A ball of radius 12 centred on the corner shared by eight 32^3 meta-cells,
/// and a small ball entirely inside meta-cell (2, 0, 0).
Volume twoBalls() {
  VectorSliceStream stream = VectorSliceStream::fromFunction({96, 64, 64}, [](int x, int y, int z) {
    const bool big = std::hypot(x - 32.f, y - 32.f, z - 32.f) < 12.f;
    const bool small = std::hypot(x - 80.f, y - 16.f, z - 16.f) < 5.f;
    return big || small ? 1.f : 0.f;
  });
  return distanceField(ingestMask(stream, {}));
}

TEST(MetaCells, PartitionFindsExactlyTheCellsWithASignChange) {
  const Volume sdf = twoBalls();
  const MetaCellPartition partition = partitionMetaCells(sdf, 32);
  // Brute force: read every meta-cell of the box and test for a sign change.
  std::vector<MetaCellIndex> expected;
  cell::MetaCellSamples samples;
  for (int k = -1; k <= 2; ++k)
    for (int j = -1; j <= 2; ++j)
      for (int i = -1; i <= 3; ++i) {
        readMetaCell(sdf, {i, j, k}, 32, samples);
        if (hasSignChange(samples, 0.f)) expected.push_back({i, j, k});
      }
  EXPECT_EQ(expected.size(), 9u);  // 8 around the corner + the small ball's
  for (const MetaCellIndex& cell : expected)
    EXPECT_NE(std::find(partition.cells.begin(), partition.cells.end(), cell), partition.cells.end())
        << cell[0] << "," << cell[1] << "," << cell[2];
  // Conservative but tight: no more than the cells next to the surface.
  EXPECT_LE(partition.cells.size(), expected.size() + 8);
  EXPECT_TRUE(std::is_sorted(partition.cells.begin(), partition.cells.end(), [](const auto& a, const auto& b) {
    return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]);
  }));
}

TEST(MetaCells, ReadMetaCellMatchesTheGridIncludingApronAndSharedBoundary) {
  const Volume sdf = twoBalls();
  const FieldGrid& grid = fieldGrid(sdf);
  auto acc = grid.getConstAccessor();
  cell::MetaCellSamples a, b;
  readMetaCell(sdf, {0, 0, 0}, 32, a);
  readMetaCell(sdf, {1, 0, 0}, 32, b);
  for (int k = -1; k <= 33; ++k)
    for (int j = -1; j <= 33; ++j)
      for (int i = -1; i <= 33; ++i) ASSERT_EQ(a.value(i, j, k), acc.getValue(openvdb::Coord(i, j, k)));
  // The shared face: a's x = 32 samples are b's x = 0 samples.
  for (int k = 0; k <= 32; ++k)
    for (int j = 0; j <= 32; ++j) ASSERT_EQ(a.value(32, j, k), b.value(0, j, k));
  // Deep inside and far outside read as the signed background.
  EXPECT_LT(a.value(32, 32, 32), 0.f);
  EXPECT_GT(a.value(0, 0, 0), 0.f);
}

// forEachActiveTile must find what OpenVDB's value iterator finds above the leaves: tiles
// at the root and in both internal levels, active ones only, beside leaves with voxels on.
TEST(MetaCells, ActiveTilesAreThoseOfTheValueIteratorWithoutItsVoxels) {
  const FieldGrid::Ptr grid = FieldGrid::create(0.f);
  FieldGrid::TreeType& tree = grid->tree();
  tree.addTile(3, openvdb::Coord(-4096, 0, 4096), 2.f, true);  // a root tile (4096^3)
  tree.addTile(2, openvdb::Coord(128, 256, 0), 3.f, true);     // in an upper internal node (128^3)
  tree.addTile(2, openvdb::Coord(256, 256, 0), 3.f, false);    // inactive: not a tile to mesh
  tree.addTile(1, openvdb::Coord(200, 8, 8), 4.f, true);       // in a lower internal node (8^3)
  tree.setValueOn(openvdb::Coord(5, 6, 7), 1.f);               // leaves' voxels
  tree.setValueOn(openvdb::Coord(-300, 40, 9), 1.f);
  std::vector<openvdb::CoordBBox> expected, found;
  for (auto value = tree.cbeginValueOn(); value; ++value)
    if (value.isTileValue()) expected.push_back(value.getBoundingBox());
  forEachActiveTile(tree, [&](const openvdb::CoordBBox& box) { found.push_back(box); });
  const auto order = [](const openvdb::CoordBBox& a, const openvdb::CoordBBox& b) {
    return std::make_tuple(a.min().x(), a.min().y(), a.min().z(), a.max().x()) <
           std::make_tuple(b.min().x(), b.min().y(), b.min().z(), b.max().x());
  };
  std::sort(expected.begin(), expected.end(), order);
  std::sort(found.begin(), found.end(), order);
  ASSERT_EQ(expected.size(), 3u);
  EXPECT_EQ(found, expected);
  // The partition of that scalar field holds the meta-cells of every tile (the root tile made
  // inactive first: its 2 M meta-cells of 32^3 are not worth a test's time).
  tree.addTile(3, openvdb::Coord(-4096, 0, 4096), 0.f, false);
  const MetaCellPartition partition = partitionMetaCells(Volume(VolumeKind::Scalar, grid, {}, "tiles"), 32, 0.5f);
  EXPECT_LE(partition.cells.size(), 6u * 6 * 6 + 3 * 3 * 3 + 2 * 3 * 3 * 3);  // each box and its neighbours
  for (const MetaCellIndex cell : {MetaCellIndex{6, 0, 0}, MetaCellIndex{5, 9, 1}, MetaCellIndex{4, 11, 3}})
    EXPECT_NE(std::find(partition.cells.begin(), partition.cells.end(), cell), partition.cells.end())
        << cell[0] << "," << cell[1] << "," << cell[2];
}

// A dense scalar field (every voxel a stored value): a ball, a slab whose faces are leaf
// faces (its crossings lie between two leaves that are each on one side), and a slab
// against the data box's face (its crossing is the cap, beyond the box, where samples read
// as outside). Every meta-cell whose samples cross the isovalue, as the contouring reads
// them, is in the partition; the meta-cells of one-sided leaves among one-sided
// neighbours are not.
TEST(MetaCells, ScalarPartitionHoldsEveryCrossingAndSkipsOneSidedBlocks) {
  constexpr int kX = 72, kY = 40, kZ = 40, kSize = 8;
  constexpr float kIso = 0.5f;
  VectorSliceStream stream = VectorSliceStream::fromFunction({kX, kY, kZ}, [](int x, int y, int z) {
    if (std::hypot(x - 19.5f, y - 20.f, z - 21.f) < 9.f) return 0.9f;
    // Not constant, so the ingest keeps leaves (a constant block would be a tile, always kept).
    if (x >= 40 && x < 48 && y >= 8 && y < 32) return 1.0f + 0.1f * static_cast<float>((x + y + z) % 3);
    if (x >= 64) return 2.0f + 0.1f * static_cast<float>(y % 2);  // against the box's x face
    return 0.1f * static_cast<float>((x * 7 + y * 3 + z) % 4);    // below the isovalue, not constant
  });
  const Volume field = ingestScalar(stream, {.background = 0.f});
  const IndexBox box{{0, 0, 0}, {kX - 1, kY - 1, kZ - 1}};
  const MetaCellPartition partition = partitionMetaCells(field, kSize, kIso, box);
  const auto inPartition = [&](const MetaCellIndex& cell) {
    return std::find(partition.cells.begin(), partition.cells.end(), cell) != partition.cells.end();
  };
  cell::MetaCellSamples samples;
  int crossed = 0, candidates = 0;
  for (int k = -1; k <= kZ / kSize; ++k)
    for (int j = -1; j <= kY / kSize; ++j)
      for (int i = -1; i <= kX / kSize; ++i) {
        readMetaCell(field, {i, j, k}, kSize, samples);
        bool in = false, out = false;
        for (int c = 0; c <= kSize; ++c)
          for (int b = 0; b <= kSize; ++b)
            for (int a = 0; a <= kSize; ++a) {
              const std::array<int, 3> p{i * kSize + a, j * kSize + b, k * kSize + c};
              bool inBox = true;
              for (int axis = 0; axis < 3; ++axis)
                inBox = inBox && p[axis] >= box.min[axis] && p[axis] <= box.max[axis];
              (inBox && samples.value(a, b, c) >= kIso ? in : out) = true;
            }
        ++candidates;
        if (!(in && out)) continue;
        ++crossed;
        EXPECT_TRUE(inPartition({i, j, k})) << i << "," << j << "," << k;
      }
  EXPECT_GT(crossed, 20);
  EXPECT_LT(static_cast<int>(partition.cells.size()), candidates);
  // Beyond the box's x = 0 face, where nothing inside reaches it: each of these meta-cells
  // holds the samples x = 0 of leaves that are outside like their neighbours, so it is
  // left out (touching any leaf, it would be in).
  for (int k = -1; k <= kZ / kSize; ++k)
    for (int j = -1; j <= kY / kSize; ++j) EXPECT_FALSE(inPartition({-1, j, k})) << j << "," << k;
}

TEST(MetaCells, RejectsBadSizes) {
  const Volume sdf = twoBalls();
  EXPECT_THROW(partitionMetaCells(sdf, 48), InputError);
  EXPECT_THROW(partitionMetaCells(sdf, 4), InputError);
}

}  // namespace
}  // namespace isovdb::volume
