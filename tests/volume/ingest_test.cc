// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/ingest.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Count.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>

#include "isovdb/volume/grids.h"
#include "support/vector_slice_stream.h"

namespace isovdb::volume {
namespace {

using test::VectorSliceStream;

/// Labels 0..3 in blobs, with a little deterministic noise, on odd dimensions so
/// blocks at the border are partial.
VectorSliceStream labelVolume() {
  return VectorSliceStream::fromFunction({37, 29, 21}, [](int x, int y, int z) {
    const float d = std::hypot(x - 18.f, y - 14.f, z - 10.f);
    float label = d < 6 ? 3.f : d < 9 ? 2.f : 0.f;
    if ((x * 7 + y * 13 + z * 29) % 31 == 0) label = 1.f;
    return label;
  });
}

TEST(IngestMask, RoundTripIsExact) {
  VectorSliceStream stream = labelVolume();
  const MaskRule rule{.labels = {2, 3}};
  const Volume volume = ingestMask(stream, rule);
  const MaskGrid& grid = maskGrid(volume);
  auto acc = grid.getConstAccessor();
  std::int64_t inside = 0;
  for (int z = 0; z < 21; ++z)
    for (int y = 0; y < 29; ++y)
      for (int x = 0; x < 37; ++x) {
        const bool expected = rule.inside(stream.at(x, y, z));
        inside += expected;
        ASSERT_EQ(acc.isValueOn(openvdb::Coord(x, y, z)), expected) << x << "," << y << "," << z;
        ASSERT_EQ(acc.getValue(openvdb::Coord(x, y, z)), expected);
      }
  EXPECT_GT(inside, 0);
  EXPECT_EQ(static_cast<std::int64_t>(grid.activeVoxelCount()), inside);
  // Nothing outside the volume's box.
  openvdb::CoordBBox bbox;
  ASSERT_TRUE(grid.tree().evalActiveVoxelBoundingBox(bbox));
  EXPECT_GE(bbox.min().x(), 0);
  EXPECT_LE(bbox.max().x(), 36);
}

TEST(IngestMask, ThresholdRule) {
  VectorSliceStream stream = labelVolume();
  const Volume volume = ingestMask(stream, MaskRule{.threshold = 1.5, .labels = {}});
  EXPECT_EQ(maskGrid(volume).activeVoxelCount(),
            static_cast<openvdb::Index64>(
                std::count_if(stream.values().begin(), stream.values().end(), [](float v) { return v > 1.5f; })));
}

TEST(IngestMask, HomogeneousBlocksBecomeTiles) {
  // A solid 128^3 block (one level-1 internal node), an 8^3 block, and one odd voxel.
  VectorSliceStream stream = VectorSliceStream::fromFunction({144, 136, 136}, [](int x, int y, int z) {
    const bool big = x < 128 && y < 128 && z < 128;
    const bool small = x >= 136 && x < 144 && y < 8 && z < 8;
    const bool single = x == 130 && y == 130 && z == 130;
    return (big || small || single) ? 1.f : 0.f;
  });
  const Volume volume = ingestMask(stream, {});
  const MaskGrid::TreeType& tree = maskGrid(volume).tree();
  EXPECT_EQ(tree.leafCount(), 1u);  // only the odd voxel needs a leaf
  EXPECT_EQ(tree.activeTileCount(), 2u);
  EXPECT_EQ(tree.getValueDepth(openvdb::Coord(5, 5, 5)), 1);        // 128^3 tile in a level-2 node
  EXPECT_EQ(tree.getValueDepth(openvdb::Coord(140, 3, 3)), 2);      // 8^3 tile in a level-1 node
  EXPECT_EQ(tree.getValueDepth(openvdb::Coord(130, 130, 130)), 3);  // voxel in a leaf
  EXPECT_EQ(tree.activeVoxelCount(), 128u * 128 * 128 + 512 + 1);
  EXPECT_LT(tree.memUsage(), 1'000'000u);  // the level-2 node's table; dense: 2.6 MB of bytes
}

TEST(IngestMask, SameTreeForAnyThreadCount) {
  auto run = [](int threads) {
    tbb::task_arena arena(threads);
    Volume volume;
    arena.execute([&] {
      VectorSliceStream stream = labelVolume();
      volume = ingestMask(stream, {});
    });
    return volume;
  };
  const Volume one = run(1), many = run(8);
  const MaskGrid& a = maskGrid(one);
  const MaskGrid& b = maskGrid(many);
  EXPECT_EQ(a.activeVoxelCount(), b.activeVoxelCount());
  EXPECT_EQ(a.tree().leafCount(), b.tree().leafCount());
  for (auto it = a.cbeginValueOn(); it; ++it) ASSERT_TRUE(b.tree().isValueOn(it.getCoord()));
}

TEST(IngestScalar, RoundTripIsExact) {
  VectorSliceStream stream = VectorSliceStream::fromFunction({19, 17, 23}, [](int x, int y, int z) {
    return x < 8 && y < 8 && z < 8 ? 5.f : std::sin(0.3f * x) * std::cos(0.2f * y) + 0.01f * z;
  });
  const Volume volume = ingestScalar(stream);
  EXPECT_EQ(volume.kind(), VolumeKind::Scalar);
  const FieldGrid& grid = fieldGrid(volume);
  auto acc = grid.getConstAccessor();
  for (int z = 0; z < 23; ++z)
    for (int y = 0; y < 17; ++y)
      for (int x = 0; x < 19; ++x) ASSERT_EQ(acc.getValue(openvdb::Coord(x, y, z)), stream.at(x, y, z));
  EXPECT_EQ(grid.tree().getValueDepth(openvdb::Coord(1, 1, 1)), 2);  // the constant block is a tile
}

// Files whose fastest axis is not the grid's x (SEG-Y: samples along time, stored as the
// grid's z): each block is filled by leaf offset, so every permutation of the axes is read.
TEST(Ingest, EveryAxisOrderPutsEachSampleAtItsGridCoordinate) {
  const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const std::array<int, 3>& order : orders) {
    VectorSliceStream stream = labelVolume();
    stream.mutableHeader().gridAxis = order;
    const auto gridCoord = [&](int x, int y, int z) {
      openvdb::Coord c;
      c[order[0]] = x;
      c[order[1]] = y;
      c[order[2]] = z;
      return c;
    };
    VectorSliceStream scalarStream = stream;
    const Volume mask = ingestMask(stream, MaskRule{.labels = {2, 3}});
    const Volume scalar = ingestScalar(scalarStream, {.background = 0.f});
    auto inside = maskGrid(mask).getConstAccessor();
    auto value = fieldGrid(scalar).getConstAccessor();
    for (int z = 0; z < 21; ++z)
      for (int y = 0; y < 29; ++y)
        for (int x = 0; x < 37; ++x) {
          const float v = stream.at(x, y, z);
          ASSERT_EQ(inside.isValueOn(gridCoord(x, y, z)), v >= 2.f) << order[0] << order[1] << order[2];
          ASSERT_EQ(value.getValue(gridCoord(x, y, z)), v) << order[0] << order[1] << order[2];
        }
  }
}

TEST(IngestScalar, BackgroundBlocksAreNotStored) {
  VectorSliceStream stream = VectorSliceStream::fromFunction(
      {64, 64, 64}, [](int x, int y, int z) { return x == 40 && y == 40 && z == 40 ? 1.f : 0.f; });
  const Volume volume = ingestScalar(stream, {.background = 0.f});
  EXPECT_EQ(fieldGrid(volume).tree().leafCount(), 1u);
}

// The ingest records the range of what it stores (Volume::stats() reads it instead of
// walking every value): NaNs and dead-band samples are not stored, background-valued
// blocks are dropped, constant blocks become tiles, and the extremes sit in different slabs.
TEST(IngestScalar, ValueRangeIsThatOfTheStoredValues) {
  for (const float deadBand : {0.0f, 0.5f}) {
    VectorSliceStream stream = VectorSliceStream::fromFunction({21, 19, 37}, [](int x, int y, int z) {
      if (x < 8 && y < 8 && z < 8) return 7.5f;         // a tile
      if (x >= 16 && y >= 16) return 0.0f;              // background blocks
      if (x == 3 && y == 12 && z == 30) return -40.0f;  // the minimum, a late slab
      if (x == 18 && y == 2 && z == 17) return 60.0f;   // the maximum, another slab
      if ((x + y + z) % 11 == 0) return std::numeric_limits<float>::quiet_NaN();
      if (z > 32) return 0.01f * std::sin(0.7f * x);  // within the 0.5 dead band
      return std::sin(0.3f * x) * std::cos(0.2f * y) + 0.05f * z;
    });
    const Volume volume = ingestScalar(stream, {.background = deadBand, .deadBand = deadBand});
    const auto extrema = openvdb::tools::minMax(fieldGrid(volume).tree());
    const GridStats stats = volume.stats();
    EXPECT_EQ(stats.minValue, extrema.min()) << deadBand;
    EXPECT_EQ(stats.maxValue, extrema.max()) << deadBand;
    EXPECT_EQ(stats.minValue, -40.0f);
    EXPECT_EQ(stats.maxValue, 60.0f);
  }
}

TEST(Ingest, CarriesGeometry) {
  VectorSliceStream stream = labelVolume();
  stream.mutableHeader().spacing = {1, 1, 1.5};
  stream.mutableHeader().origin = {10, 0, -2};
  const Volume volume = ingestMask(stream, {});
  EXPECT_EQ(volume.geometry().spacing[2], 1.5);
  EXPECT_EQ(volume.geometry().origin[0], 10);
  EXPECT_FALSE(volume.geometry().isUniform());
}

}  // namespace
}  // namespace isovdb::volume
