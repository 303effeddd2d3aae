// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/qef.h.
#include "isovdb/cell/qef.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace isovdb::cell {
namespace {

TEST(Qef, CornerOfThreePlanesIsExact) {
  const std::vector<Vec3f> points{{1.5f, 0.2f, 0.9f}, {1.5f, 0.7f, 0.1f}, {0.3f, 2.5f, 0.6f},
                                  {0.8f, 2.5f, 0.2f}, {0.4f, 0.6f, 3.5f}, {0.9f, 0.1f, 3.5f}};
  const std::vector<Vec3f> normals{{1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}};
  const QefSolution s = solveQef(points, normals);
  EXPECT_EQ(s.rank, 3);
  EXPECT_NEAR(s.point[0], 1.5f, 1e-5f);
  EXPECT_NEAR(s.point[1], 2.5f, 1e-5f);
  EXPECT_NEAR(s.point[2], 3.5f, 1e-5f);
  EXPECT_NEAR(s.error, 0.0f, 1e-8f);
}

TEST(Qef, DegenerateSystemStaysAtTheMassPointOnThePlane) {
  // All normals equal: rank 1; the solution moves only along the normal.
  const Vec3f n{0.0f, 0.6f, 0.8f};
  std::vector<Vec3f> points, normals;
  for (int i = 0; i < 5; ++i) {
    const float u = static_cast<float>(i);
    // points on the plane n . x = 2
    points.push_back({u * 0.7f, 2.0f / 0.6f - u * 0.8f / 0.6f * 0.5f, u * 0.5f});
    normals.push_back(n);
  }
  const QefSolution s = solveQef(points, normals);
  EXPECT_EQ(s.rank, 1);
  EXPECT_NEAR(n[0] * s.point[0] + n[1] * s.point[1] + n[2] * s.point[2], 2.0f, 1e-4f);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.point[a], s.massPoint[a], 1e-4f);
}

TEST(Qef, TruncationIgnoresNearlyParallelNormals) {
  // Two almost parallel planes: truncating the tiny singular value keeps the
  // vertex near the mass point instead of shooting along the crease.
  const std::vector<Vec3f> points{{0, 0, 0}, {1, 0, 0}};
  const float e = 1e-3f;
  const std::vector<Vec3f> normals{{0, 0, 1}, {e, 0, std::sqrt(1 - e * e)}};
  const QefSolution s = solveQef(points, normals, {.singularValueThreshold = 0.1f});
  EXPECT_EQ(s.rank, 1);
  EXPECT_NEAR(s.point[0], 0.5f, 1e-3f);
  const QefSolution sharp = solveQef(points, normals, {.singularValueThreshold = 0.0f});
  EXPECT_EQ(sharp.rank, 2);
}

TEST(Qef, EmptyInput) {
  const QefSolution s = solveQef({}, {});
  EXPECT_EQ(s.rank, 0);
}

}  // namespace
}  // namespace isovdb::cell
