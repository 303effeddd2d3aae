// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/validate.h"

#include <gtest/gtest.h>

#include <limits>
#include <utility>

#include <tbb/global_control.h>

#include "isovdb/errors.h"
#include "mesh/test_meshes.h"

namespace isovdb::mesh {
namespace {

using test::octahedron;
using test::sphere;
using test::torus;

void append(Mesh& mesh, const Mesh& other) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
  for (const Triangle& t : other.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void expectClosedSurface(const MeshReport& r, std::int64_t euler, std::int64_t genus) {
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.nonManifoldVertices, 0);
  EXPECT_EQ(r.inconsistentlyOrientedEdges, 0);
  EXPECT_EQ(r.degenerateTriangles, 0);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
  EXPECT_EQ(r.eulerCharacteristic, euler);
  EXPECT_EQ(r.edges * 2, r.triangles * 3);
  ASSERT_EQ(r.components, 1);
  ASSERT_EQ(r.componentReports.size(), 1u);
  const ComponentReport& c = r.componentReports[0];
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.manifold);
  EXPECT_EQ(c.eulerCharacteristic, euler);
  EXPECT_EQ(c.genus, genus);
  EXPECT_EQ(c.triangles, r.triangles);
  EXPECT_EQ(c.vertices, r.referencedVertices);
  EXPECT_EQ(c.edges, r.edges);
}

TEST(ValidateMesh, OctahedronIsAClosedGenusZeroSurface) {
  const MeshReport r = validateMesh(octahedron());
  EXPECT_EQ(r.vertices, 6);
  EXPECT_EQ(r.referencedVertices, 6);
  EXPECT_EQ(r.triangles, 8);
  EXPECT_EQ(r.edges, 12);
  expectClosedSurface(r, 2, 0);
}

TEST(ValidateMesh, SubdividedSphereIsAClosedGenusZeroSurface) {
  const Mesh mesh = sphere(4);
  ASSERT_EQ(mesh.triangles.size(), 8u * 256u);
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.vertices, static_cast<std::int64_t>(mesh.positions.size()));
  expectClosedSurface(r, 2, 0);
}

TEST(ValidateMesh, TorusHasGenusOne) {
  const MeshReport r = validateMesh(torus(24, 12));
  EXPECT_EQ(r.triangles, 24 * 12 * 2);
  expectClosedSurface(r, 0, 1);
}

TEST(ValidateMesh, MissingTriangleLeavesABoundary) {
  Mesh mesh = sphere(1);
  mesh.triangles.erase(mesh.triangles.begin() + 5);
  const MeshReport r = validateMesh(mesh);
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_EQ(r.boundaryEdges, 3);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.eulerCharacteristic, 1);
  ASSERT_EQ(r.componentReports.size(), 1u);
  EXPECT_FALSE(r.componentReports[0].closed);
  EXPECT_EQ(r.componentReports[0].genus, -1);
}

TEST(ValidateMesh, ThreeTrianglesOnOneEdgeAreNonManifold) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.edges, 7);
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.boundaryEdges, 6);
  EXPECT_EQ(r.nonManifoldVertices, 0);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.components, 1);
  EXPECT_FALSE(r.componentReports[0].manifold);
}

TEST(ValidateMesh, ClosedSurfaceWithAFinOnOneEdgeIsNotClosed) {
  Mesh mesh = octahedron();
  mesh.positions.push_back({2, 2, 0});
  mesh.triangles.push_back({0, 2, 6});  // a third triangle on edge {0, 2}
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.boundaryEdges, 2);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.componentReports[0].genus, -1);
}

TEST(ValidateMesh, TwoTetrahedraSharingOneVertexGiveOneNonManifoldVertex) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  // Two closed, outward-oriented tetrahedra meeting only at vertex 0.
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.nonManifoldVertices, 1);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(r.inconsistentlyOrientedEdges, 0);
  EXPECT_TRUE(r.closed);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.eulerCharacteristic, 7 - 12 + 8);
  EXPECT_EQ(r.componentReports[0].genus, -1);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
}

TEST(ValidateMesh, BowtieHasOneNonManifoldVertex) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}};
  mesh.triangles = {{0, 2, 1}, {0, 3, 4}};
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.nonManifoldVertices, 1);
  EXPECT_EQ(r.boundaryEdges, 6);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.components, 1);
}

TEST(ValidateMesh, FlippedTriangleGivesThreeInconsistentEdges) {
  Mesh mesh = octahedron();
  std::swap(mesh.triangles[3][0], mesh.triangles[3][1]);
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.inconsistentlyOrientedEdges, 3);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
}

TEST(ValidateMesh, CountsCollapsedAndFlatTriangles) {
  Mesh mesh = octahedron();
  mesh.triangles.push_back({0, 0, 2});  // repeated index: ignored by the topology
  // Three distinct vertices on a line, and a triangle with two coincident points.
  mesh.positions.push_back({5, 0, 0});
  mesh.positions.push_back({6, 1, 1});
  mesh.positions.push_back({8, 3, 3});
  mesh.positions.push_back({6, 1, 1});
  mesh.positions.push_back({7, 0, 0});
  mesh.triangles.push_back({6, 7, 8});
  mesh.triangles.push_back({6, 9, 7});
  mesh.triangles.push_back({6, 7, 10});  // proper
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.triangles, 12);
  EXPECT_EQ(r.degenerateTriangles, 3);
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(r.componentReports[0].triangles, 8);
  EXPECT_TRUE(r.componentReports[0].closed);
  EXPECT_EQ(r.componentReports[0].genus, 0);
  EXPECT_EQ(r.componentReports[1].triangles, 3);
  EXPECT_EQ(r.referencedVertices, 11);
  EXPECT_EQ(r.eulerCharacteristic, r.referencedVertices - r.edges + 11);
  // The flat triangles are skipped by the self-intersection test even though
  // {6, 7, 8} lies along the proper triangle's edge.
  EXPECT_EQ(r.selfIntersectingPairs, 0);
}

TEST(ValidateMesh, ReportsComponentsInOrderOfTheirFirstTriangle) {
  Mesh mesh = torus(16, 8);
  append(mesh, octahedron({20, 0, 0}));
  append(mesh, octahedron({-20, 0, 0}));
  const MeshReport r = validateMesh(mesh);
  ASSERT_EQ(r.components, 3);
  EXPECT_EQ(r.componentReports[0].genus, 1);
  EXPECT_EQ(r.componentReports[0].triangles, 256);
  EXPECT_EQ(r.componentReports[1].genus, 0);
  EXPECT_EQ(r.componentReports[1].vertices, 6);
  EXPECT_EQ(r.componentReports[2].genus, 0);
  EXPECT_EQ(r.eulerCharacteristic, 0 + 2 + 2);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
}

TEST(ValidateMesh, UnreferencedVerticesDoNotCount) {
  Mesh mesh = octahedron();
  mesh.positions.push_back({9, 9, 9});
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.vertices, 7);
  EXPECT_EQ(r.referencedVertices, 6);
  EXPECT_EQ(r.eulerCharacteristic, 2);
}

TEST(ValidateMesh, CountsSelfIntersectionsUnlessDisabled) {
  Mesh mesh = octahedron();
  append(mesh, octahedron({0.5f, 0.25f, 0.125f}));
  const MeshReport r = validateMesh(mesh);
  EXPECT_GT(r.selfIntersectingPairs, 0);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(validateMesh(mesh, {.selfIntersections = false}).selfIntersectingPairs, -1);
}

TEST(ValidateMesh, EmptyMesh) {
  const MeshReport r = validateMesh(Mesh{});
  EXPECT_EQ(r.triangles, 0);
  EXPECT_EQ(r.components, 0);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
  EXPECT_TRUE(r.closed);
}

TEST(ValidateMesh, RejectsInvalidIndicesAndNonFiniteCoordinates) {
  Mesh mesh = octahedron();
  mesh.triangles[6][1] = 6;
  try {
    validateMesh(mesh);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 6 references vertex 6"), std::string::npos) << e.what();
  }
  Mesh nan = octahedron();
  nan.positions[3][2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(validateMesh(nan), InputError);
}

TEST(ValidateMesh, DoesNotDependOnTheThreadCount) {
  Mesh mesh = torus(64, 32);
  append(mesh, sphere(3));
  mesh.triangles.erase(mesh.triangles.begin() + 100);
  const MeshReport parallel = validateMesh(mesh);
  MeshReport serial;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = validateMesh(mesh);
  }
  EXPECT_EQ(parallel.edges, serial.edges);
  EXPECT_EQ(parallel.boundaryEdges, serial.boundaryEdges);
  EXPECT_EQ(parallel.selfIntersectingPairs, serial.selfIntersectingPairs);
  ASSERT_EQ(parallel.componentReports.size(), serial.componentReports.size());
  for (std::size_t c = 0; c < serial.componentReports.size(); ++c) {
    EXPECT_EQ(parallel.componentReports[c].triangles, serial.componentReports[c].triangles);
    EXPECT_EQ(parallel.componentReports[c].genus, serial.componentReports[c].genus);
  }
  EXPECT_EQ(serial.boundaryEdges, 3);
  EXPECT_EQ(serial.componentReports[0].genus, -1);
  EXPECT_EQ(serial.componentReports[1].genus, 0);
}

}  // namespace
}  // namespace isovdb::mesh
