// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/meta_cells.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(MetaCells, RejectsBadSizes) {
  const Volume sdf = twoBalls();
  EXPECT_THROW(partitionMetaCells(sdf, 48), InputError);
  EXPECT_THROW(partitionMetaCells(sdf, 4), InputError);
}

}  // namespace
}  // namespace isovdb::volume
