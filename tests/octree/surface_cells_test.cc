// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/surface_cells.h: the surface cells listed from the
// phase bits are the regular construction's surface leaves, in the same order.
#include "isovdb/octree/surface_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace isovdb::octree {
namespace {

constexpr cell::ContourSettings kRegular{.method = cell::ContourMethod::Regular};

/// The regular construction's leaves that hold a vertex: 1-voxel cells with corners of both phases.
std::vector<OctreeLeaf> crossedLeavesOfRegularTree(const cell::MetaCellSamples& samples, float iso) {
  cell::ContourSettings settings = kRegular;
  settings.iso = iso;
  const LinearOctree tree = buildOctree(samples, settings, {});
  std::vector<OctreeLeaf> crossed;
  for (const OctreeLeaf& l : tree.leaves())
    if (l.cornerSigns != 0 && l.cornerSigns != 0xFF) crossed.push_back(l);
  return crossed;
}

void expectSameCells(const cell::MetaCellSamples& samples, float iso) {
  const std::vector<OctreeLeaf> expected = crossedLeavesOfRegularTree(samples, iso);
  const LinearOctree tree = surfaceCellTree(samples, iso);
  ASSERT_EQ(tree.leafCount(), expected.size());
  ASSERT_GT(expected.size(), 0u);
  EXPECT_EQ(tree.metaCellSize(), samples.size);
  EXPECT_EQ(tree.origin(), samples.origin);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const OctreeLeaf& a = tree.leaf(i);
    const OctreeLeaf& b = expected[i];
    ASSERT_EQ(a.key, b.key) << "leaf " << i;
    ASSERT_EQ(a.origin, b.origin) << "leaf " << i;
    ASSERT_EQ(a.size, 1);
    ASSERT_EQ(a.depth, b.depth);
    ASSERT_EQ(a.cornerSigns, b.cornerSigns) << "leaf " << i;
    ASSERT_TRUE(a.surface);
    ASSERT_FALSE(a.complex);
    ASSERT_LT(a.vertexTruncation, 0.0f);  // no vertex placed: contouring solves the QEF
    // Lookups in the partial tree find the cell and nothing where no cell is kept.
    ASSERT_EQ(tree.findLeafContainingVoxel(a.origin), static_cast<std::int64_t>(i));
  }
}

TEST(SurfaceCellTree, SameCellsAsTheRegularConstructionOnASphereAcrossRuns) {
  // S = 128: a row of cells is read in runs of 63, so cells at x = 62, 63, 125, 126 test the seams of the runs.
  const cell::MetaCellSamples samples = cell::makeMetaCellSamples(128, {256, -128, 0}, [](int x, int y, int z) {
    const double dx = x - 256 - 64.3, dy = y + 128 - 63.6, dz = z - 64.1;  // global coordinates
    return std::sqrt(dx * dx + dy * dy + dz * dz) - 62.5;
  });
  expectSameCells(samples, 0.0f);
  expectSameCells(samples, 1.25f);  // another isovalue: other cells
}

TEST(SurfaceCellTree, SameCellsAsTheRegularConstructionOnRandomSigns) {
  // Integer samples in {-1, 0, 1}: samples on the isovalue (inside), every configuration, the apron too.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> d(-1, 1);
  for (const int size : {16, 64}) {
    SCOPED_TRACE(size);
    const cell::MetaCellSamples samples =
        cell::makeMetaCellSamples(size, {0, 0, 0}, [&](int, int, int) { return static_cast<float>(d(rng)); });
    expectSameCells(samples, 0.0f);
    expectSameCells(samples, -1.0f);
  }
}

TEST(SurfaceCellTree, OnlyRegularModeWithUnitCellsReadsOnlySurfaceCells) {
  EXPECT_TRUE(contourReadsOnlySurfaceCells(kRegular, {}, 128));
  EXPECT_TRUE(contourReadsOnlySurfaceCells(kRegular, {.minDepth = 3}, 64));
  EXPECT_FALSE(contourReadsOnlySurfaceCells(kRegular, {.finestCellSize = 2}, 128));
  EXPECT_FALSE(contourReadsOnlySurfaceCells(kRegular, {.maxDepth = 5}, 128));
  EXPECT_FALSE(contourReadsOnlySurfaceCells(kRegular, {.detectInteriorComponents = false}, 128));
  EXPECT_FALSE(contourReadsOnlySurfaceCells({.method = cell::ContourMethod::Adaptive}, {}, 128));
}

TEST(SurfaceCellTree, BuildContourTreeChoosesByTheSettings) {
  const cell::MetaCellSamples samples = cell::makeMetaCellSamples(32, {0, 0, 0}, [](int x, int y, int z) {
    return std::sqrt((x - 16.2) * (x - 16.2) + (y - 15.9) * (y - 15.9) + (z - 16.4) * (z - 16.4)) - 9.0;
  });
  const std::size_t surface = buildContourTree(samples, kRegular).leafCount();
  const std::size_t full = buildOctree(samples, kRegular).leafCount();
  EXPECT_EQ(surface, crossedLeavesOfRegularTree(samples, 0.0f).size());
  EXPECT_GT(full, surface);  // the full tree keeps its empty leaves
  EXPECT_EQ(buildContourTree(samples, kRegular, {.finestCellSize = 2}).leafCount(),
            buildOctree(samples, kRegular, {.finestCellSize = 2}).leafCount());
}

}  // namespace
}  // namespace isovdb::octree
