// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/unit_edge_crossings.h: every bipolar unit edge's
// crossing is intersectEdge's, every other edge has none.
#include "isovdb/contour/unit_edge_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace isovdb::contour {
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

}  // namespace
}  // namespace isovdb::contour
