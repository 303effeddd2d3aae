// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The sampled two-sided Hausdorff distance of `isovdb compare`.
#include "isovdb/mesh/mesh_distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::mesh {
namespace {

/// The unit square [0, size]^2 at height z, two triangles.
Mesh square(float size, float z) {
  Mesh m;
  m.positions = {{0, 0, z}, {size, 0, z}, {size, size, z}, {0, size, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(MeshDistance, IdenticalMeshesAreZeroApart) {
  const MeshDistance d = compareMeshes(square(4, 0), square(4, 0));
  EXPECT_EQ(d.hausdorff(), 0.0);
  EXPECT_GT(d.aToB.samples, 4u);  // the triangles' insides are sampled, not only the corners
}

TEST(MeshDistance, ParallelSquaresAreTheirGapApart) {
  const MeshDistance d = compareMeshes(square(4, 0), square(4, 0.3f));
  EXPECT_NEAR(d.aToB.max, 0.3, 1e-6);
  EXPECT_NEAR(d.bToA.mean, 0.3, 1e-6);
  EXPECT_NEAR(d.hausdorff(), 0.3, 1e-6);
  EXPECT_NEAR(d.upperBound(), 0.3 + 0.25 / std::sqrt(3.0), 1e-6);
}

TEST(MeshDistance, TheTwoSidesDifferWhereOneMeshCoversMore) {
  // B is A's square doubled in x and y: every point of A lies on B, B's far corner
  // is 4 * sqrt(2) from A, and the samples find it.
  const MeshDistance d = compareMeshes(square(4, 0), square(8, 0));
  EXPECT_EQ(d.aToB.max, 0.0);
  EXPECT_NEAR(d.bToA.max, 4.0 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(d.bToA.farthest[0], 8.0, 1e-6);
  EXPECT_NEAR(d.bToA.farthest[1], 8.0, 1e-6);
  EXPECT_LT(d.bToA.p99, d.bToA.max + 1e-9);
}

TEST(MeshDistance, RejectsEmptyMeshesAndBadSpacing) {
  EXPECT_THROW(compareMeshes(Mesh{}, square(1, 0)), InputError);
  EXPECT_THROW(compareMeshes(square(1, 0), square(1, 0), {.spacing = 0.0}), InputError);
  Mesh broken = square(1, 0);
  broken.triangles.push_back({0, 1, 7});
  EXPECT_THROW(compareMeshes(broken, square(1, 0)), InputError);
}

}  // namespace
}  // namespace isovdb::mesh
