// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The distance field held one layer of meta-cells at a time (volume/slab_band.h):
// every layer's meta-cells and every meta-cell's samples are those of the whole
// distanceField(), bit for bit (also below the origin, across thin sheets, random
// voxels, interiors far from any leaf, closing and odd chunk sizes), and what it
// holds at once is a fraction of the band.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>
#include <string>

#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/meta_cells.h"
#include "isovdb/volume/slab_band.h"

namespace isovdb::volume {
namespace {

/// A mask of the voxels [lo, lo + n)^3 where `inside` holds, built straight into a grid
/// (so it may lie below the origin).
Volume maskOf(int lo, int n, const std::function<bool(int, int, int)>& inside) {
  MaskGrid::Ptr grid = MaskGrid::create(false);
  auto acc = grid->getAccessor();
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (inside(x, y, z)) acc.setValueOn(openvdb::Coord(lo + x, lo + y, lo + z));
  return Volume(VolumeKind::Mask, grid, {}, "test mask");
}

void expectSameAsTheWholeField(const Volume& mask, const DistanceFieldOptions& options, int size, int apron,
                               const std::string& what) {
  SCOPED_TRACE(what);
  const Volume whole = distanceField(mask, options);
  const MetaCellPartition partition = partitionMetaCells(whole, size);
  ASSERT_FALSE(partition.cells.empty());
  SlabBand band(mask, options, size, apron);
  std::vector<MetaCellIndex> layered;
  cell::MetaCellSamples fromLayers, fromWhole;
  for (int k = band.firstLayer(); k < band.endLayer(); ++k)
    for (const MetaCellIndex& index : band.advanceTo(k, 0.f)) {
      layered.push_back(index);
      band.read(index, fromLayers);
      readMetaCell(whole, index, size, fromWhole, apron);
      ASSERT_EQ(fromLayers.values.size(), fromWhole.values.size());
      ASSERT_EQ(std::memcmp(fromLayers.values.data(), fromWhole.values.data(), fromWhole.values.size() * sizeof(float)),
                0)
          << "meta-cell " << index[0] << "," << index[1] << "," << index[2];
    }
  EXPECT_EQ(layered, partition.cells);
  const SlabBand::Figures figures = band.figures();
  EXPECT_EQ(figures.activeVoxels, static_cast<std::int64_t>(fieldGrid(whole).activeVoxelCount()));
  EXPECT_EQ(figures.leafCount, static_cast<std::int64_t>(fieldGrid(whole).tree().leafCount()));
  openvdb::CoordBBox box;
  ASSERT_TRUE(fieldGrid(whole).tree().evalActiveVoxelBoundingBox(box));
  EXPECT_EQ(figures.bboxMin, (std::array<int, 3>{box.min().x(), box.min().y(), box.min().z()}));
  EXPECT_EQ(figures.bboxMax, (std::array<int, 3>{box.max().x(), box.max().y(), box.max().z()}));
}

TEST(SlabBand, EveryLayerReadsWhatTheWholeFieldHolds) {
  // Balls, a one-voxel sheet and a large block whose interior holds no leaf of the
  // band (read from the mask's side), all below the origin.
  const Volume shapes = maskOf(-53, 90, [](int x, int y, int z) {
    const auto ball = [&](int cx, int cy, int cz, int r) {
      return (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) <= r * r;
    };
    const bool sheet = z == 70 && x > 5 && x < 80 && y > 5 && y < 80;
    const bool block = x >= 40 && x < 86 && y >= 10 && y < 60 && z >= 8 && z < 60;
    return ball(20, 20, 20, 12) || ball(30, 60, 40, 9) || sheet || block;
  });
  expectSameAsTheWholeField(shapes, {}, 16, 1, "shapes, S 16");
  expectSameAsTheWholeField(shapes, {}, 32, 2, "shapes, S 32, apron 2");
  expectSameAsTheWholeField(shapes, {.chunkSize = 24}, 16, 1, "shapes, chunk 24");
  expectSameAsTheWholeField(shapes, {.closingSteps = 1}, 16, 1, "shapes, closing 1");
  expectSameAsTheWholeField(shapes, {.halfWidth = 5}, 32, 1, "shapes, half-width 5");
  // Random voxels: ambiguous faces, diagonal contacts, specks.
  for (const double density : {0.1, 0.5}) {
    std::mt19937 random(static_cast<unsigned>(density * 100));
    std::bernoulli_distribution on(density);
    std::vector<char> voxels(40 * 40 * 40);
    for (char& v : voxels) v = on(random);
    const Volume mask = maskOf(-7, 40, [&](int x, int y, int z) { return voxels[(z * 40 + y) * 40 + x] != 0; });
    expectSameAsTheWholeField(mask, {}, 16, 1, "random voxels, density " + std::to_string(density));
  }
}

TEST(SlabBand, HoldsAFractionOfTheBandAtOnce) {
  // A tall cylinder: 25 layers of 16 voxels, of which a few are held at a time.
  const Volume cylinder = maskOf(0, 400, [](int x, int y, int z) {
    return z > 4 && z < 395 && (x - 30) * (x - 30) + (y - 30) * (y - 30) <= 20 * 20;
  });
  SlabBand band(cylinder, {.chunkSize = 16}, 16, 1);
  std::size_t cells = 0;
  for (int k = band.firstLayer(); k < band.endLayer(); ++k) cells += band.advanceTo(k, 0.f).size();
  EXPECT_GT(cells, 0u);
  const SlabBand::Figures figures = band.figures();
  const auto wholeBytes =
      static_cast<std::int64_t>(fieldGrid(distanceField(cylinder, {.chunkSize = 16})).tree().memUsage());
  EXPECT_GT(figures.peakBytes, 0);
  EXPECT_LT(figures.peakBytes, wholeBytes / 4) << "held " << figures.peakBytes << " of " << wholeBytes;
}

}  // namespace
}  // namespace isovdb::volume
