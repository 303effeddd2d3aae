// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/unit_leaf_index.h: the same answers as the tree's
// own lookups, on trees of 1-voxel leaves only and of mixed sizes.
#include "isovdb/octree/unit_leaf_index.h"

#include <gtest/gtest.h>

#include <cmath>

#include "isovdb/octree/build.h"
#include "isovdb/octree/surface_cells.h"

namespace isovdb::octree {
namespace {

void expectSameLookups(const LinearOctree& tree) {
  const UnitLeafIndex index(tree);
  const int s = tree.metaCellSize();
  // Every voxel of a few slabs: both boundaries, the middle, and just outside.
  for (const int z : {-1, 0, 1, s / 2 - 1, s / 2, s / 3, s - 1, s})
    for (int y = -1; y <= s; ++y)
      for (int x = -1; x <= s; ++x) {
        const std::array<int, 3> v{x, y, z};
        ASSERT_EQ(index.findLeafContainingVoxel(v), tree.findLeafContainingVoxel(v)) << x << "," << y << "," << z;
        if (x < 0 || y < 0 || z < 0 || x >= s || y >= s || z >= s) continue;
        for (int axis = 0; axis < 3; ++axis)
          ASSERT_EQ(index.leavesAroundEdge(v, axis), tree.leavesAroundEdge(v, axis)) << x << "," << y << "," << z;
      }
}

TEST(UnitLeafIndex, SameLookupsAsTheTree) {
  // S = 128: rows of two 64-bit words; a sphere crossing both.
  const cell::MetaCellSamples sphere = cell::makeMetaCellSamples(128, {0, 0, 0}, [](int x, int y, int z) {
    return std::sqrt((x - 70.2) * (x - 70.2) + (y - 60.7) * (y - 60.7) + (z - 64.4) * (z - 64.4)) - 50.0;
  });
  const cell::ContourSettings regular{.method = cell::ContourMethod::Regular};
  SCOPED_TRACE("surface cells");
  expectSameLookups(surfaceCellTree(sphere, 0.0f));
  SCOPED_TRACE("regular octree (1-voxel and larger leaves)");
  expectSameLookups(buildOctree(sphere, regular));
  SCOPED_TRACE("adaptive octree");
  expectSameLookups(buildOctree(sphere, {.method = cell::ContourMethod::Adaptive}));
}

}  // namespace
}  // namespace isovdb::octree
