// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Loops fanned again where another fan crosses fewer triangles: a saddle quad over a
// horizontal triangle, fanned along its ridge (crossing) or its valley (clear).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "isovdb/mesh/self_intersection.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/reservoir/untangle_loops.h"

namespace isovdb::reservoir {
namespace {

/// Cell 0: the saddle v0..v3 (v0 and v2 up at 0.2, v1 and v3 down at -0.2), fanned as
/// `fan0`; cell 1: a horizontal triangle at height 0.1 around the saddle's middle, which
/// the ridge's fans (along v0-v2, or from a centre above it) cross and the valley's do not.
mesh::Mesh saddleOverTriangle(const std::vector<mesh::Triangle>& fan0, std::vector<std::uint32_t>& cells) {
  mesh::Mesh m;
  m.positions = {{0, 0, 0.2f},       {1, 0, -0.2f},       {1, 1, 0.2f},       {0, 1, -0.2f},  // the saddle
                 {0.3f, 0.3f, 0.1f}, {0.7f, 0.35f, 0.1f}, {0.5f, 0.7f, 0.1f},                 // the triangle
                 {0.5f, 0.5f, 0.15f}};                                                        // a centre
  m.normals.assign(m.positions.size(), {0, 0, 1});
  m.triangles = fan0;
  cells.assign(fan0.size(), 0);
  m.triangles.push_back({4, 5, 6});
  cells.push_back(1);
  return m;
}

/// The directed boundary edges of cell 0's triangles: what a refanned loop must keep.
std::set<std::pair<std::uint32_t, std::uint32_t>> boundaryOfCell0(const mesh::Mesh& m,
                                                                  const std::vector<std::uint32_t>& cells) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (cells[t] == 0)
      for (int e = 0; e < 3; ++e) edges.emplace(m.triangles[t][e], m.triangles[t][(e + 1) % 3]);
  std::set<std::pair<std::uint32_t, std::uint32_t>> boundary;
  for (const auto& [a, b] : edges)
    if (!edges.count({b, a})) boundary.emplace(a, b);
  return boundary;
}

TEST(UntangleLoops, TheRidgeFanGivesWayToTheValleyFan) {
  std::vector<std::uint32_t> cells;
  mesh::Mesh m = saddleOverTriangle({{0, 1, 2}, {0, 2, 3}}, cells);
  const auto boundary = boundaryOfCell0(m, cells);
  const UntangleResult r = untangleLoops(m, cells);
  EXPECT_EQ(r.pairsBefore, 1);  // the triangle crosses the ridge fan's first triangle
  EXPECT_EQ(r.pairsAfter, 0);
  EXPECT_TRUE(r.remainingPairs.empty());
  EXPECT_EQ(r.loopsRefanned, 1);
  EXPECT_EQ(mesh::countSelfIntersections(m), 0);
  ASSERT_EQ(m.triangles.size(), 3u);
  ASSERT_EQ(cells.size(), m.triangles.size());
  EXPECT_EQ(boundaryOfCell0(m, cells), boundary) << "the loop's boundary and winding are kept";
  EXPECT_EQ(std::count(cells.begin(), cells.end(), 0), 2);
  EXPECT_EQ(m.positions.size(), 7u) << "the centre, which no triangle uses, is removed";
}

TEST(UntangleLoops, ACentreFanGivesWayAndItsCentreIsDropped) {
  std::vector<std::uint32_t> cells;
  mesh::Mesh m = saddleOverTriangle({{7, 0, 1}, {7, 1, 2}, {7, 2, 3}, {7, 3, 0}}, cells);
  const auto boundary = boundaryOfCell0(m, cells);
  ASSERT_GT(mesh::countSelfIntersections(m), 0);
  const UntangleResult r = untangleLoops(m, cells);
  EXPECT_EQ(r.pairsAfter, 0);
  EXPECT_EQ(mesh::countSelfIntersections(m), 0);
  EXPECT_EQ(m.positions.size(), 7u) << "the unused centre is removed";
  EXPECT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(boundaryOfCell0(m, cells), boundary);
  const mesh::MeshReport report = mesh::validateMesh(m);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
}

TEST(UntangleLoops, ALoopThatCrossesNothingStays) {
  std::vector<std::uint32_t> cells;
  mesh::Mesh m = saddleOverTriangle({{1, 2, 3}, {1, 3, 0}}, cells);  // the valley already
  const std::vector<mesh::Triangle> before = m.triangles;
  const UntangleResult r = untangleLoops(m, cells);
  EXPECT_EQ(r.pairsBefore, 0);
  EXPECT_EQ(r.loopsRefanned, 0);
  EXPECT_EQ(m.triangles, before);
}

TEST(UntangleLoops, AFanDoesNotTakeADiagonalThatIsAnotherCellsEdge) {
  // The valley's diagonal v1-v3 is an edge of a triangle hanging below it (cell 2): the
  // valley fan would give that edge three triangles. The ridge stays, with its pair.
  std::vector<std::uint32_t> cells;
  mesh::Mesh m = saddleOverTriangle({{0, 1, 2}, {0, 2, 3}}, cells);
  m.positions.push_back({0.5f, 0.5f, -1.0f});
  m.normals.push_back({0, 0, 1});
  m.triangles.push_back({3, 1, 8});
  cells.push_back(2);
  const UntangleResult r = untangleLoops(m, cells);
  EXPECT_EQ(r.pairsBefore, 1);
  EXPECT_EQ(r.loopsRefanned, 0);
  EXPECT_EQ(r.pairsAfter, 1);
  EXPECT_EQ(mesh::validateMesh(m).nonManifoldEdges, 0);
}

TEST(UntangleLoops, PairsEverywhereAreLeftAsTheyAre) {
  // 1,200 saddles over their triangles, side by side: a pair for every three triangles,
  // more than 1,000 + 1 % of them, as where a grid's cells fold over each other.
  mesh::Mesh m;
  std::vector<std::uint32_t> cells;
  for (std::uint32_t copy = 0; copy < 1200; ++copy) {
    std::vector<std::uint32_t> copyCells;
    const mesh::Mesh one = saddleOverTriangle({{0, 1, 2}, {0, 2, 3}}, copyCells);
    const auto first = static_cast<std::uint32_t>(m.positions.size());
    for (const auto& p : one.positions) m.positions.push_back({p[0] + 2.0f * static_cast<float>(copy), p[1], p[2]});
    m.normals.insert(m.normals.end(), one.normals.begin(), one.normals.end());
    for (const auto& t : one.triangles) m.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
    for (const auto c : copyCells) cells.push_back(2 * copy + c);
  }
  const std::vector<mesh::Triangle> before = m.triangles;
  const UntangleResult r = untangleLoops(m, cells);
  EXPECT_EQ(r.pairsBefore, 1200);
  EXPECT_TRUE(r.skipped);
  EXPECT_EQ(r.pairsAfter, 1200);
  EXPECT_EQ(m.triangles.size(), before.size());
}

}  // namespace
}  // namespace isovdb::reservoir
