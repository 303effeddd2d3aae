// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/cell/trilinear.h.
#include "isovdb/cell/trilinear.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "isovdb/cell/dual_vertex.h"

namespace isovdb::cell {
namespace {

/// A trilinear polynomial: trilinear interpolation of its samples reproduces it and its
/// gradient exactly, in every cell.
double poly(double x, double y, double z) {
  return 0.3 + 0.7 * x - 0.2 * y + 0.45 * z + 0.05 * x * y - 0.08 * y * z + 0.03 * x * z + 0.011 * x * y * z;
}

TEST(Trilinear, ReproducesATrilinearFieldAndItsGradient) {
  const std::array<int, 3> origin{-3, 5, 2};
  const MetaCellSamples samples =
      makeMetaCellSamples(8, origin, [](int x, int y, int z) { return static_cast<float>(poly(x, y, z)); });
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> at(0.0f, 8.0f);
  const float iso = 0.25f;
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3f p{at(rng), at(rng), at(rng)};  // meta-cell offsets
    const double x = p[0] + origin[0], y = p[1] + origin[1], z = p[2] + origin[2];
    const TrilinearSample f = trilinearAt(samples, p, iso);
    EXPECT_NEAR(f.value, poly(x, y, z) - iso, 1e-4);
    EXPECT_NEAR(f.gradient[0], 0.7 + 0.05 * y + 0.03 * z + 0.011 * y * z, 1e-4);
    EXPECT_NEAR(f.gradient[1], -0.2 + 0.05 * x - 0.08 * z + 0.011 * x * z, 1e-4);
    EXPECT_NEAR(f.gradient[2], 0.45 - 0.08 * y + 0.03 * x + 0.011 * x * y, 1e-4);
  }
}

TEST(Trilinear, DistanceToAPlanesLevelIsExact) {
  // f = (x + 2y - 2z) / 3: a distance field; its level 0.5 lies 0.5 from the level 0.
  const MetaCellSamples samples = makeMetaCellSamples(
      4, {0, 0, 0}, [](int x, int y, int z) { return static_cast<float>((x + 2.0 * y - 2.0 * z) / 3.0); });
  EXPECT_NEAR(distanceToLevel(samples, {1.5f, 1.0f, 1.0f}, 0.0f), 0.5f, 1e-5f);
  EXPECT_NEAR(distanceToLevel(samples, {1.5f, 1.0f, 1.0f}, 0.5f), 0.0f, 1e-5f);
  EXPECT_NEAR(distanceToLevel(samples, {2.0f, 3.25f, 0.5f}, -1.0f), (2.0f + 6.5f - 1.0f) / 3.0f + 1.0f, 1e-5f);
}

TEST(Trilinear, LevelWithinTrustsTheFirstOrderDistanceInCrossedCellsAndElseARegularVertex) {
  // A two-voxel-thin plate, samples z = 4 and 5 inside (value <= 0): between them the field
  // is -0.5 throughout, its gradient zero, so the first-order distance is infinite.
  const MetaCellSamples samples = makeMetaCellSamples(8, {0, 0, 0}, [](int, int, int z) {
    return z == 4 || z == 5 ? -0.5f : z < 4 ? 3.5f - z : z - 5.5f;
  });
  const DualVertexOptions iso0{};
  const Vec3f middle{3.5f, 2.5f, 4.5f};
  EXPECT_TRUE(std::isinf(distanceToLevel(samples, middle, 0.0f)));
  // The level crosses the unit edges z 3-4 and 5-6 at z = 3.5 and 5.5, and full-resolution
  // contouring puts each unit cell's vertex at the middle of its crossings, (i + 0.5, j + 0.5,
  // 3.5) below the plate's middle: a voxel away.
  EXPECT_TRUE(levelWithin(samples, middle, iso0, 1.0f));
  EXPECT_FALSE(levelWithin(samples, middle, iso0, 0.95f));
  // The witnesses are those vertices, points of regular mode's mesh, not the crossings (the
  // nearest crossing lies sqrt(1.25) = 1.118 from this point, the nearest vertex sqrt(1.05) = 1.025).
  EXPECT_FALSE(levelWithin(samples, {3.3f, 2.4f, 4.5f}, iso0, 1.02f));
  EXPECT_TRUE(levelWithin(samples, {3.3f, 2.4f, 4.5f}, iso0, 1.03f));
  // Inside a cell the level crosses the first-order distance decides (a plane: exact).
  const Vec3f crossed{3.3f, 2.6f, 5.75f};  // field 0.25 there, gradient 1; the vertex 0.335 away
  EXPECT_TRUE(levelWithin(samples, crossed, iso0, 0.25f));
  EXPECT_FALSE(levelWithin(samples, crossed, iso0, 0.2f));
  // Outside such cells it extrapolates, and only a vertex counts: here the first-order
  // distance is 1.75, the nearest vertex (3.5, 2.5, 5.5) sqrt(3.1125) = 1.764 away.
  const Vec3f above{3.3f, 2.6f, 7.25f};
  EXPECT_NEAR(distanceToLevel(samples, above, 0.0f), 1.75f, 1e-5f);
  EXPECT_FALSE(levelWithin(samples, above, iso0, 1.76f));
  EXPECT_TRUE(levelWithin(samples, above, iso0, 1.77f));
  // A radius beyond the samples is searched within them; a NaN point has no witness.
  EXPECT_TRUE(levelWithin(samples, middle, iso0, 1e30f));
  EXPECT_FALSE(levelWithin(samples, {NAN, 1.0f, 1.0f}, iso0, 1.0f));
}

}  // namespace
}  // namespace isovdb::cell
