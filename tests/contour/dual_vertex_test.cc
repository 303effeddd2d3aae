// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/dual_vertex.h, gradient.h and edge_intersection.h
// on planes, sharp edges and corners sampled on a grid.
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/contour/leaf_groups.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "isovdb/cell/edge_intersection.h"
#include "isovdb/cell/gradient.h"
#include "isovdb/octree/build.h"

namespace isovdb::contour {
namespace {

using cell::makeMetaCellSamples;
using cell::MetaCellSamples;
using cell::Vec3f;
using V3 = std::array<double, 3>;

V3 unit(V3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 toV3(const Vec3f& v) { return {v[0], v[1], v[2]}; }

/// Signed distance-like field of the intersection of half-spaces n_i . (x - c) <= 0.
cell::MetaCellSamples halfSpaces(const std::vector<V3>& normals, const V3& c, std::array<int, 3> origin) {
  return cell::makeMetaCellSamples(16, origin, [&](int x, int y, int z) {
    double v = -1e9;
    for (const V3& n : normals) v = std::max(v, dot(n, sub({double(x), double(y), double(z)}, c)));
    return v;
  });
}

bool insideCell(const Vec3f& p, std::array<int, 3> lo, int size) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < static_cast<float>(lo[a]) || p[a] > static_cast<float>(lo[a] + size)) return false;
  return true;
}

TEST(Gradient, PrewittIsExactOnLinearFields) {
  const cell::MetaCellSamples s =
      cell::makeMetaCellSamples(8, {3, -2, 5}, [](int x, int y, int z) { return 0.5 * x - 2.0 * y + 0.25 * z; });
  for (int k = 0; k <= 8; k += 4) {
    const Vec3f g = cell::prewittGradient(s, 4, 8, k);
    EXPECT_NEAR(g[0], 0.5f, 1e-5f);
    EXPECT_NEAR(g[1], -2.0f, 1e-5f);
    EXPECT_NEAR(g[2], 0.25f, 1e-5f);
  }
  const Vec3f n = cell::normalized(cell::prewittGradientOnEdge(s, {0, 0, 0}, 0, 0.3f));
  EXPECT_NEAR(n[1], -2.0f / std::sqrt(0.25f + 4.0f + 0.0625f), 1e-5f);
}

TEST(EdgeIntersection, InterpolatesBetweenTheTransitionSamples) {
  cell::MetaCellSamples s = cell::makeMetaCellSamples(8, {0, 0, 0}, [](int x, int, int) { return x - 2.25; });
  cell::EdgeIntersection hit;
  ASSERT_TRUE(cell::intersectEdge(s, {0, 1, 1}, 0, 8, 0.0f, hit));
  EXPECT_NEAR(hit.point[0], 2.25f, 1e-6f);
  EXPECT_EQ(hit.point[1], 1.0f);
  EXPECT_NEAR(hit.normal[0], 1.0f, 1e-6f);
  EXPECT_EQ(hit.transitions, 1);
  EXPECT_FALSE(cell::intersectEdge(s, {4, 0, 0}, 1, 8, 0.0f, hit));  // all outside
  // An exact-iso sample is inside: the crossing is at that sample.
  s.value(5, 0, 0) = 0.0f;
  ASSERT_TRUE(cell::intersectEdge(s, {3, 0, 0}, 0, 4, 0.0f, hit));
  EXPECT_NEAR(hit.point[0], 5.0f, 1e-6f);
  EXPECT_EQ(hit.transitions, 2);
}

TEST(DualVertex, PlaneSharpEdgeAndCornerWithin005Voxel) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  double worst[3] = {0, 0, 0};
  for (int trial = 0; trial < 20; ++trial) {
    const std::array<int, 3> origin{100 * trial, -37, 1000};
    const std::array<int, 3> cell{4, 4, 4};
    const V3 c{origin[0] + 8 + jitter(rng), origin[1] + 8 + jitter(rng), origin[2] + 8 + jitter(rng)};
    // Plane.
    {
      const V3 n = unit({0.3 + jitter(rng), 0.5, 0.8});
      const cell::MetaCellSamples s = halfSpaces({n}, c, origin);
      const cell::DualVertex v = cell::computeDualVertex(s, cell, 8);
      ASSERT_TRUE(v.valid());
      const V3 p = toV3(v.position);
      const double d = std::abs(dot(n, sub(p, c)));
      worst[0] = std::max(worst[0], d);
      EXPECT_LT(d, 0.05) << "plane, trial " << trial;
      EXPECT_TRUE(
          insideCell({v.position[0] - origin[0], v.position[1] - origin[1], v.position[2] - origin[2]}, cell, 8));
    }
    // Sharp edge: two planes at about 90 degrees; distance to the crease line.
    {
      const V3 n1 = unit({1.0, 0.15 + 0.2 * jitter(rng), 0.1});
      const V3 n2 = unit({0.1 * jitter(rng), 1.0, -0.2});
      const cell::MetaCellSamples s = halfSpaces({n1, n2}, c, origin);
      const cell::DualVertex v = cell::computeDualVertex(s, cell, 8);
      ASSERT_TRUE(v.valid());
      const V3 dir = unit(cross(n1, n2));
      const V3 w = sub(toV3(v.position), c);
      const double along = dot(w, dir);
      const V3 perp{w[0] - along * dir[0], w[1] - along * dir[1], w[2] - along * dir[2]};
      const double d = std::sqrt(dot(perp, perp));
      worst[1] = std::max(worst[1], d);
      EXPECT_LT(d, 0.05) << "edge, trial " << trial;
    }
    // Corner: three planes.
    {
      const V3 n1 = unit({1.0, 0.1 * jitter(rng), 0.2});
      const V3 n2 = unit({-0.1, 1.0, 0.1 * jitter(rng)});
      const V3 n3 = unit({0.2 * jitter(rng), 0.1, 1.0});
      const cell::MetaCellSamples s = halfSpaces({n1, n2, n3}, c, origin);
      const cell::DualVertex v = cell::computeDualVertex(s, cell, 8);
      ASSERT_TRUE(v.valid());
      const V3 w = sub(toV3(v.position), c);
      const double d = std::sqrt(dot(w, w));
      worst[2] = std::max(worst[2], d);
      EXPECT_LT(d, 0.05) << "corner, trial " << trial;
      EXPECT_EQ(v.rank, 3);
    }
  }
  std::printf(
      "[ QEF on 8-voxel cells, 20 trials ] worst distance to the feature: plane %.4f, edge %.4f, corner %.4f voxel\n",
      worst[0], worst[1], worst[2]);
}

TEST(DualVertex, DegenerateSystemGivesAPointOnThePlaneInsideTheCell) {
  // Axis-aligned plane z = 5.3: all normals equal.
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {0, 0, 0}, [](int, int, int z) { return z - 5.3; });
  const cell::DualVertex v = cell::computeDualVertex(s, {0, 0, 4}, 4);
  ASSERT_TRUE(v.valid());
  EXPECT_EQ(v.rank, 1);
  EXPECT_NEAR(v.position[2], 5.3f, 1e-5f);
  EXPECT_TRUE(insideCell(v.position, {0, 0, 4}, 4));
  EXPECT_EQ(v.intersections, 4);
}

TEST(DualVertex, MinimiserOutsideTheCellFallsBackToTheMassPoint) {
  // Two nearly parallel planes crossing far outside the cell: with no
  // truncation the minimiser leaves the cell.
  const V3 c{8.2, 8.1, 8.4};
  const V3 n1 = unit({0.05, 0.0, 1.0}), n2 = unit({-0.05, 0.0, 1.0});
  // Crease at x = c.x; the cell [0,4] in x is far from it along a flat wedge.
  const cell::MetaCellSamples s = halfSpaces({n1, n2}, c, {0, 0, 0});
  const cell::DualVertex v =
      cell::computeDualVertex(s, {0, 4, 6}, 4, 0x0fff, {.iso = 0.0f, .singularValueThreshold = 0.0f});
  ASSERT_TRUE(v.valid());
  EXPECT_TRUE(insideCell(v.position, {0, 4, 6}, 4));
  EXPECT_TRUE(v.massPointFallback);
}

TEST(DualVertex, EdgeSubsetUsesOnlyThoseEdges) {
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {0, 0, 0}, [](int x, int y, int z) {
    return std::sqrt((x - 0.5) * (x - 0.5) + (y - 0.4) * (y - 0.4) + (z - 0.6) * (z - 0.6)) - 2.5;
  });
  const cell::DualVertex all = cell::computeDualVertex(s, {0, 0, 0}, 4);
  ASSERT_TRUE(all.valid());
  const std::uint16_t bipolar = all.edges;
  const std::uint16_t first = static_cast<std::uint16_t>(bipolar & (~bipolar + 1));  // lowest bipolar edge
  const cell::DualVertex one = cell::computeDualVertex(s, {0, 0, 0}, 4, first);
  EXPECT_EQ(one.edges, first);
  EXPECT_EQ(one.intersections, 1);
  EXPECT_FALSE(cell::computeDualVertex(s, {0, 0, 0}, 4, static_cast<std::uint16_t>(~bipolar & 0x0fff)).valid());
}

TEST(DualVertex, GroupVerticesAreInsideTheirCellsAndDeterministic) {
  // placeGroupVertices (leaf_groups.h): one vertex per DMC group of every leaf, both modes.
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(64, {64, 0, 0}, [](int x, int y, int z) {
    return 2.5 * std::sin(0.3 * x) + 2.0 * std::cos(0.23 * y) + 1.5 * std::sin(0.19 * z + 0.1 * y) + 0.2;
  });
  std::vector<std::vector<mesh::Vec3f>> runs;
  octree::LinearOctree tree;
  std::vector<std::uint32_t> firstVertex;
  const cell::ContourSettings settings{.method = cell::ContourMethod::Adaptive};
  for (int threads : {1, 2, 8}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tree = octree::buildOctree(s, settings, {.minDepth = 3, .qefTolerance = -1.0f});
      std::vector<std::uint8_t> configs;
      for (const auto& leaf : tree.leaves()) configs.push_back(leaf.cornerSigns);
      const LeafGroups groups = groupLeaves(s, tree, std::move(configs), settings.iso, settings.manifoldFix);
      firstVertex = groups.firstVertex;
      runs.push_back(placeGroupVertices(s, tree, groups, cell::dualVertexOptions(settings)));
    });
  }
  std::size_t withVertices = 0;
  for (std::size_t i = 0; i < tree.leafCount(); ++i) {
    const octree::OctreeLeaf& l = tree.leaf(i);
    EXPECT_EQ(firstVertex[i + 1] > firstVertex[i], l.bipolarEdges() != 0) << i;
    withVertices += firstVertex[i + 1] > firstVertex[i];
    const std::array<int, 3> lo{l.origin[0] + 64, l.origin[1], l.origin[2]};
    for (std::uint32_t v = firstVertex[i]; v < firstVertex[i + 1]; ++v) {
      ASSERT_TRUE(insideCell(runs[0][v], lo, l.size)) << i;
      for (std::size_t r = 1; r < runs.size(); ++r) ASSERT_EQ(runs[r][v], runs[0][v]);
    }
  }
  EXPECT_GT(withVertices, 100u);
}

}  // namespace
}  // namespace isovdb::contour
