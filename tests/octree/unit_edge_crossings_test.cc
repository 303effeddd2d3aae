// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/unit_edge_crossings.h: every bipolar unit edge's
// crossing is intersectEdge's, every other edge has none; a coarse cell's dual vertex
// read from the table is computeDualVertex's.
#include "isovdb/octree/unit_edge_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/edge_intersection.h"

namespace isovdb::octree {
namespace {

void expectIntersectEdgesCrossings(const cell::MetaCellSamples& samples, float iso, bool sharpFeatures) {
  const UnitEdgeCrossings crossings(samples, iso, sharpFeatures);
  const int s = samples.size;
  std::size_t bipolar = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int z = 0; z <= s; ++z)
      for (int y = 0; y <= s; ++y)
        for (int x = 0; x <= s; ++x) {
          std::array<int, 3> start{x, y, z};
          if (start[static_cast<std::size_t>(axis)] == s) continue;  // the edge would leave [0, S]^3
          std::array<int, 3> end = start;
          ++end[static_cast<std::size_t>(axis)];
          const bool expected = cell::isInside(samples.value(start), iso) != cell::isInside(samples.value(end), iso);
          const cell::EdgeIntersection* found = crossings.find(start, axis);
          ASSERT_EQ(found != nullptr, expected) << axis << ": " << x << "," << y << "," << z;
          if (!expected) continue;
          ++bipolar;
          cell::EdgeIntersection hit;
          ASSERT_TRUE(cell::intersectEdge(samples, start, axis, 1, iso, hit, sharpFeatures));
          ASSERT_EQ(found->point, hit.point);
          ASSERT_EQ(found->normal, hit.normal);
        }
  EXPECT_EQ(crossings.size(), bipolar);
  EXPECT_GT(bipolar, 0u);
}

TEST(UnitEdgeCrossings, EveryBipolarEdgeHasIntersectEdgesCrossing) {
  // S = 128: a row holds 129 edge starts, three 64-bit words.
  const cell::MetaCellSamples sphere = cell::makeMetaCellSamples(128, {-64, 0, 64}, [](int x, int y, int z) {
    const double dx = x + 64 - 63.6, dy = y - 64.2, dz = z - 64 - 65.1;
    return std::sqrt(dx * dx + dy * dy + dz * dz) - 63.0;
  });
  expectIntersectEdgesCrossings(sphere, 0.0f, false);
  expectIntersectEdgesCrossings(sphere, 0.0f, true);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> d(-1, 1);
  const cell::MetaCellSamples random =
      cell::makeMetaCellSamples(16, {0, 0, 0}, [&](int, int, int) { return static_cast<float>(d(rng)); });
  expectIntersectEdgesCrossings(random, 0.0f, false);
}

/// Every cell of `size` (a grid of them over the block): cellDualVertex with the table gives
/// computeDualVertex's vertex bit for bit, and findFirst the crossing intersectEdge finds on
/// each of its edges. Returns how many cells had an edge crossed more than once.
int expectCoarseVerticesAsComputed(const cell::MetaCellSamples& samples, int size, bool sharpFeatures) {
  const UnitEdgeCrossings crossings(samples, 0.0f, sharpFeatures);
  const cell::DualVertexOptions options{
      .iso = 0.0f, .singularValueThreshold = 0.1f, .massPointOnly = false, .sharpFeatures = sharpFeatures};
  int multiple = 0;
  for (int z = 0; z + size <= samples.size; z += size)
    for (int y = 0; y + size <= samples.size; y += size)
      for (int x = 0; x + size <= samples.size; x += size) {
        const std::array<int, 3> origin{x, y, z};
        bool several = false;
        for (int axis = 0; axis < 3; ++axis) {
          cell::EdgeIntersection hit;
          const bool found = cell::intersectEdge(samples, origin, axis, size, 0.0f, hit, sharpFeatures);
          const cell::EdgeIntersection* first = crossings.findFirst(origin, axis, size);
          EXPECT_EQ(first != nullptr, found) << "edge from " << x << "," << y << "," << z << " along " << axis;
          if (first == nullptr || !found) continue;
          EXPECT_EQ(first->point, hit.point);
          EXPECT_EQ(first->normal, hit.normal);
          several = several || hit.transitions > 1;
        }
        multiple += several ? 1 : 0;
        const cell::DualVertex table = cellDualVertex(samples, origin, size, 0x0fff, options, &crossings);
        const cell::DualVertex own = cell::computeDualVertex(samples, origin, size, 0x0fff, options);
        EXPECT_EQ(table.valid(), own.valid());
        EXPECT_EQ(table.position, own.position) << "cell " << x << "," << y << "," << z << " of " << size;
        EXPECT_EQ(table.qefError, own.qefError);
        EXPECT_EQ(table.edges, own.edges);
      }
  return multiple;
}

TEST(UnitEdgeCrossings, CoarseCellsReadTheSameVertices) {
  // A wavy field: coarse edges crossed once, and (the ripples) some crossed two or three
  // times, whose ends then have one sign and give no crossing.
  const cell::MetaCellSamples waves = cell::makeMetaCellSamples(32, {0, 0, 0}, [](int x, int y, int z) {
    return static_cast<float>(std::sin(0.45 * x) + std::cos(0.37 * y) + 0.6 * std::sin(0.29 * z + 0.3 * x) - 0.2);
  });
  for (const bool sharp : {false, true})
    for (const int size : {2, 4, 8, 16}) {
      const int multiple = expectCoarseVerticesAsComputed(waves, size, sharp);
      if (size >= 8) {
        EXPECT_GT(multiple, 0) << "size " << size << ": no edge crossed twice";
      }
    }
}

}  // namespace
}  // namespace isovdb::octree
