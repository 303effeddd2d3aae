// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/weld.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <tuple>

#include "isovdb/errors.h"
#include "isovdb/mesh/validate.h"

namespace isovdb::mesh {
namespace {

/// Octahedron as a soup: every triangle has its own three vertices.
Mesh octahedronSoup() {
  const Vec3f p[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const Triangle faces[8] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  Mesh mesh;
  for (const Triangle& f : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const std::uint32_t v : f) {
      mesh.positions.push_back(p[v]);
      mesh.normals.push_back({p[v][0] * 2, p[v][1] * 2, p[v][2] * 2});
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

TEST(WeldVertices, TurnsASoupIntoAClosedMesh) {
  Mesh mesh = octahedronSoup();
  const Mesh soup = mesh;
  ASSERT_FALSE(validateMesh(soup).closed);

  EXPECT_EQ(weldVertices(mesh), 24u - 6u);
  ASSERT_EQ(mesh.positions.size(), 6u);
  ASSERT_EQ(mesh.normals.size(), 6u);
  ASSERT_EQ(mesh.triangles.size(), 8u);
  // First-occurrence order: the soup's first triangle was {0, 2, 4}.
  EXPECT_EQ(mesh.positions[0], (Vec3f{1, 0, 0}));
  EXPECT_EQ(mesh.positions[1], (Vec3f{0, 1, 0}));
  EXPECT_EQ(mesh.positions[2], (Vec3f{0, 0, 1}));
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
  // Every corner still sits where it was, and carries its normal.
  for (std::size_t t = 0; t < 8; ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(mesh.positions[mesh.triangles[t][k]], soup.positions[soup.triangles[t][k]]);
      EXPECT_EQ(mesh.normals[mesh.triangles[t][k]], soup.normals[soup.triangles[t][k]]);
    }

  const MeshReport report = validateMesh(mesh);
  EXPECT_TRUE(report.closed);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.eulerCharacteristic, 2);
}

TEST(WeldVertices, KeepsAMeshWithoutDuplicatesUnchanged) {
  Mesh mesh = octahedronSoup();
  weldVertices(mesh);
  const Mesh welded = mesh;
  EXPECT_EQ(weldVertices(mesh), 0u);
  EXPECT_EQ(mesh.positions, welded.positions);
  EXPECT_EQ(mesh.triangles, welded.triangles);
  EXPECT_EQ(mesh.normals, welded.normals);
}

TEST(WeldVertices, ComparesBitPatternsNotValues) {
  Mesh mesh;
  mesh.positions = {{0.f, 1.f, 2.f}, {-0.f, 1.f, 2.f}, {0.f, 1.f, 2.f}, {0.f, std::nextafter(1.f, 2.f), 2.f}};
  mesh.triangles = {{0, 1, 3}, {2, 1, 3}};
  EXPECT_EQ(weldVertices(mesh), 1u);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_TRUE(std::signbit(mesh.positions[1][0]));
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (Triangle{0, 1, 2}));
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(WeldVertices, KeepsCollapsedTrianglesForValidateToReport) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_EQ(weldVertices(mesh), 1u);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 0}));
  EXPECT_EQ(validateMesh(mesh).degenerateTriangles, 1);
}

TEST(WeldVertices, MatchesAReferenceOnManyRandomDuplicates) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(0, 20);
  Mesh mesh;
  for (int i = 0; i < 30000; ++i)
    mesh.positions.push_back({float(coord(rng)), float(coord(rng)) * 0.5f, float(coord(rng)) * 0.25f});
  std::uniform_int_distribution<std::uint32_t> vertex(0, 29999);
  for (int i = 0; i < 20000; ++i) mesh.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
  const Mesh before = mesh;

  std::map<std::tuple<float, float, float>, std::uint32_t> firstIndex;
  std::vector<Vec3f> expectedPositions;
  for (const Vec3f& p : before.positions)
    if (firstIndex.emplace(std::make_tuple(p[0], p[1], p[2]), expectedPositions.size()).second)
      expectedPositions.push_back(p);

  EXPECT_EQ(weldVertices(mesh), before.positions.size() - expectedPositions.size());
  EXPECT_EQ(mesh.positions, expectedPositions);
  for (std::size_t t = 0; t < before.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3f& p = before.positions[before.triangles[t][k]];
      EXPECT_EQ(mesh.triangles[t][k], firstIndex.at(std::make_tuple(p[0], p[1], p[2])));
    }
}

TEST(WeldVertices, RejectsInvalidMeshesAndLeavesThemUnchanged) {
  Mesh mesh = octahedronSoup();
  mesh.triangles.push_back({0, 1, 24});
  const Mesh before = mesh;
  try {
    weldVertices(mesh);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 8 references vertex 24"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mesh.positions, before.positions);

  Mesh badNormals = octahedronSoup();
  badNormals.normals.pop_back();
  EXPECT_THROW(weldVertices(badNormals), InputError);
  EXPECT_EQ(badNormals.positions.size(), 24u);
}

}  // namespace
}  // namespace isovdb::mesh
