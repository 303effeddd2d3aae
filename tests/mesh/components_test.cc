// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/components.h"

#include <gtest/gtest.h>

#include "mesh/test_meshes.h"

namespace isovdb::mesh {
namespace {

/// `b`'s vertices and triangles appended after `a`'s, their triangles interleaved so that
/// a part's triangles are not contiguous.
Mesh interleaved(const Mesh& a, const Mesh& b) {
  Mesh out;
  out.positions = a.positions;
  out.positions.insert(out.positions.end(), b.positions.begin(), b.positions.end());
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  for (std::size_t t = 0; t < std::max(a.triangles.size(), b.triangles.size()); ++t) {
    if (t < b.triangles.size())
      out.triangles.push_back({b.triangles[t][0] + offset, b.triangles[t][1] + offset, b.triangles[t][2] + offset});
    if (t < a.triangles.size()) out.triangles.push_back(a.triangles[t]);
  }
  return out;
}

TEST(Components, SplitsInFirstTriangleOrderAndKeepsEachPartsOrder) {
  const Mesh ring = test::torus(8, 6);
  const Mesh ball = test::octahedron({10, 0, 0});
  Mesh both = interleaved(ring, ball);
  both.positions.push_back({99, 99, 99});  // unused: dropped
  const std::vector<Mesh> parts = splitComponents(both);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].positions, ball.positions);  // the octahedron's triangle comes first
  EXPECT_EQ(parts[0].triangles, ball.triangles);
  EXPECT_EQ(parts[1].positions, ring.positions);
  EXPECT_EQ(parts[1].triangles, ring.triangles);
}

TEST(Components, RootsAreTheSmallestVertexAndFollowOnlyJoiningTriangles) {
  Mesh strip;
  strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  strip.triangles = {{3, 4, 1}, {0, 1, 2}};
  EXPECT_EQ(vertexComponentRoots(strip), (std::vector<std::uint32_t>{0, 0, 0, 0, 0}));
  const auto firstOnly = vertexComponentRoots(strip, [](std::size_t t) { return t == 0; });
  EXPECT_EQ(firstOnly, (std::vector<std::uint32_t>{0, 1, 2, 1, 1}));
}

TEST(Components, NormalsTravelWithTheirVertices) {
  Mesh ball = test::octahedron();
  for (const auto& p : ball.positions) ball.normals.push_back(p);
  Mesh two = interleaved(test::octahedron({5, 0, 0}), ball);
  two.normals.assign(two.positions.begin(), two.positions.begin() + 6);  // the first octahedron's
  two.normals.insert(two.normals.end(), ball.normals.begin(), ball.normals.end());
  const std::vector<Mesh> parts = splitComponents(two);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].normals, ball.normals);
  EXPECT_EQ(parts[1].normals, parts[1].positions);
}

}  // namespace
}  // namespace isovdb::mesh
