// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/pinched_vertices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "isovdb/mesh/validate.h"

namespace isovdb::mesh {
namespace {

/// Two open fans of two triangles each around vertex 0, touching only there (a bow tie
/// with a second blade on each side), as two sheets leave a capped mesh at one cap vertex.
Mesh bowTie() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {1, -1, 0}, {-1, -1, 0}, {-1, 0, 0}, {-1, 1, 0}};
  mesh.normals.assign(mesh.positions.size(), Vec3f{0, 0, 1});
  mesh.triangles = {{0, 3, 2}, {0, 2, 1}, {0, 6, 5}, {0, 5, 4}};
  return mesh;
}

TEST(SplitPinchedVertices, GivesEachFanItsOwnVertexApartFromTheOthers) {
  Mesh mesh = bowTie();
  ASSERT_EQ(validateMesh(mesh).nonManifoldVertices, 1);
  {
    // A copy left at the same point: the blades touch there without sharing a vertex.
    Mesh copied = mesh;
    copied.positions.push_back(copied.positions[0]);
    copied.triangles[2][0] = copied.triangles[3][0] = 7;
    ASSERT_TRUE(validateMesh(copied).manifold);
    ASSERT_GT(validateMesh(copied).selfIntersectingPairs, 0);
  }
  EXPECT_EQ(splitPinchedVertices(mesh), 1u);
  ASSERT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.normals.size(), 8u);
  // The first fan keeps vertex 0; the second (triangles 2 and 3) uses the copy.
  EXPECT_EQ(mesh.triangles[0][0], 0u);
  EXPECT_EQ(mesh.triangles[1][0], 0u);
  EXPECT_EQ(mesh.triangles[2][0], 7u);
  EXPECT_EQ(mesh.triangles[3][0], 7u);
  // Each moved 10^-3 towards its own blade: +x for the first, -x for the second.
  EXPECT_NEAR(mesh.positions[0][0], 1e-3f, 1e-6f);
  EXPECT_NEAR(mesh.positions[7][0], -1e-3f, 1e-6f);
  const MeshReport report = validateMesh(mesh);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
  EXPECT_EQ(report.components, 2);
}

TEST(SplitPinchedVertices, LeavesAManifoldMeshAlone) {
  Mesh mesh;
  mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  mesh.triangles.pop_back();  // open, one hole: still manifold
  const Mesh before = mesh;
  EXPECT_EQ(splitPinchedVertices(mesh), 0u);
  EXPECT_EQ(mesh.positions, before.positions);
  EXPECT_EQ(mesh.triangles, before.triangles);
}

}  // namespace
}  // namespace isovdb::mesh
