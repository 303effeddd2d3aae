// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/self_intersection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/global_control.h>

#include "isovdb/errors.h"
#include "mesh/test_meshes.h"

namespace isovdb::mesh {
namespace {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
using test::octahedron;
using test::sphere;
using test::torus;

Mesh triangles(std::vector<Vec3f> positions, std::vector<Triangle> tris) {
  Mesh mesh;
  mesh.positions = std::move(positions);
  mesh.triangles = std::move(tris);
  return mesh;
}

TEST(SelfIntersection, ClosedSurfacesHaveNone) {
  EXPECT_EQ(countSelfIntersections(octahedron()), 0);
  EXPECT_EQ(countSelfIntersections(sphere(5)), 0);  // 8192 triangles, all neighbours touch
  EXPECT_EQ(countSelfIntersections(torus(60, 30)), 0);
  EXPECT_EQ(countSelfIntersections(Mesh{}), 0);
}

TEST(SelfIntersection, TrianglePiercingAnother) {
  const Mesh mesh =
      triangles({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {1, 2, 0}}, {{0, 1, 2}, {3, 4, 5}});
  Pairs pairs;
  EXPECT_EQ(countSelfIntersections(mesh, &pairs), 1);
  EXPECT_EQ(pairs, (Pairs{{0, 1}}));
}

TEST(SelfIntersection, TetrahedronThroughATriangleGivesThreePairs) {
  // The three faces around the apex below z = 0 cross the big triangle; the top face does not.
  const Mesh mesh = triangles({{-10, -10, 0}, {10, -10, 0}, {0, 10, 0}, {0, 0, -1}, {1, 0, 1}, {-1, 1, 1}, {-1, -1, 1}},
                              {{0, 1, 2}, {3, 5, 4}, {3, 6, 5}, {3, 4, 6}, {4, 5, 6}});
  Pairs pairs;
  EXPECT_EQ(countSelfIntersections(mesh, &pairs), 3);
  EXPECT_EQ(pairs, (Pairs{{0, 1}, {0, 2}, {0, 3}}));
}

TEST(SelfIntersection, InterpenetratingOctahedra) {
  Mesh mesh = octahedron();
  const Mesh other = octahedron({1, 0, 0});  // its vertex (0,0,0) is the first one's centre
  for (const Triangle& t : other.triangles) mesh.triangles.push_back({t[0] + 6, t[1] + 6, t[2] + 6});
  mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
  // The second octahedron's vertex 1 is (0,0,0), the first's centre, and the first's vertex 0
  // is the second's centre. Each +x face of the first (one per octant (±y, ±z)) crosses the
  // second's -x face of the same octant and touches those of the two neighbouring octants at
  // a point such as (0.5, 0.5, 0): 4 x 3 pairs. No other face reaches into the other solid.
  Pairs pairs;
  EXPECT_EQ(countSelfIntersections(mesh, &pairs), 12);
  for (const auto& [a, b] : pairs) {
    EXPECT_LT(a, 8u);
    EXPECT_GE(b, 8u);
  }
}

TEST(SelfIntersection, TouchingCountsButDisjointDoesNot) {
  // A vertex of the second triangle lies inside the first (no shared index).
  EXPECT_EQ(countSelfIntersections(
                triangles({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {1, 1, 1}, {2, 1, 1}}, {{0, 1, 2}, {3, 4, 5}})),
            1);
  // The same, lifted by the smallest step above the plane.
  const float up = std::nextafter(0.f, 1.f);
  EXPECT_EQ(countSelfIntersections(
                triangles({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, up}, {1, 1, 1}, {2, 1, 1}}, {{0, 1, 2}, {3, 4, 5}})),
            0);
  // Parallel planes, overlapping boxes in x and y.
  EXPECT_EQ(countSelfIntersections(
                triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, {{0, 1, 2}, {3, 4, 5}})),
            0);
}

TEST(SelfIntersection, SharedEdgeIntersectsOnlyWhenFoldedOntoItsNeighbour) {
  const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0.25f, 0.5f, 0}};
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {1, 0, 3}})), 0);  // a crease
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {1, 0, 4}})), 0);  // flat, opposite sides
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {1, 0, 5}})), 1);  // folded over, coplanar
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 1, 5}})), 1);  // same, other winding
}

TEST(SelfIntersection, SharedVertexIntersectsOnlyBeyondTheVertex) {
  const std::vector<Vec3f> p = {{0, 0, 0},    {2, 0, 0}, {0, 2, 0}, {-1, 0, 0},    {0, -1, 0},       {1, 0.5f, 0},
                                {0.5f, 1, 0}, {0, 0, 1}, {0, 3, 0}, {-1, 1.5f, 0}, {0.5f, 0.5f, -1}, {0.5f, 0.5f, 1}};
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 3, 4}})), 0);    // coplanar, apart
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 3, 7}})), 0);    // fan, not coplanar
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 5, 6}})), 1);    // coplanar, inside
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 8, 9}})), 1);    // coplanar, along an edge
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 10, 11}})), 1);  // opposite edge pierces
}

TEST(SelfIntersection, DuplicateTrianglesIntersect) {
  const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {0, 1, 2}})), 1);
  EXPECT_EQ(countSelfIntersections(triangles(p, {{0, 1, 2}, {2, 1, 0}})), 1);
}

// Copies of one triangle (same indices) are tested once for the whole set: #26's
// 20,000 copies made 2e8 pair tests. The counts and the pair list stay those of
// every pair tested on its own: the copies of a piercing triangle each pierce, and a
// copy's neighbour across a shared edge is still not an intersection.
TEST(SelfIntersection, CopiesOfATriangleCountEveryPairWithoutTestingEachPair) {
  const std::vector<Vec3f> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {2, 2, 1}, {4, 4, 0}};
  // {0,1,2} three times (two with other index orders), {3,4,5} (pierces it) twice,
  // {1,6,2} (its neighbour across the edge 1-2) once.
  const Mesh mesh = triangles(p, {{0, 1, 2}, {3, 4, 5}, {1, 2, 0}, {1, 6, 2}, {2, 0, 1}, {4, 3, 5}});
  Pairs pairs;
  EXPECT_EQ(countSelfIntersections(mesh, &pairs), 3 + 1 + 3 * 2);
  const Pairs expected = {{0, 1}, {0, 2}, {0, 4}, {0, 5}, {1, 2}, {1, 4}, {1, 5}, {2, 4}, {2, 5}, {4, 5}};
  EXPECT_EQ(pairs, expected);

  constexpr std::int64_t kCopies = 200000;  // 2e10 pairs: as many tests would take hours
  Mesh copies = triangles(p, std::vector<Triangle>(kCopies, Triangle{0, 1, 2}));
  copies.triangles.push_back({1, 6, 2});
  EXPECT_EQ(countSelfIntersections(copies), kCopies * (kCopies - 1) / 2);
}

TEST(SelfIntersection, UnweldedNeighboursTouch) {
  // Two triangles on one geometric edge, but with their own copies of its vertices.
  const Mesh mesh =
      triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}}, {{0, 1, 2}, {3, 4, 5}});
  EXPECT_EQ(countSelfIntersections(mesh), 1);
}

TEST(SelfIntersection, SkipsDegenerateTriangles) {
  const Mesh mesh = triangles({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {1, 1, 0.5f}},
                              {{0, 1, 2}, {3, 4, 5}, {3, 3, 4}, {0, 3, 4}});
  // {3,4,5} is collinear and {3,3,4} has a repeated index; {0,3,4} is proper and pierces
  // {0,1,2}? It shares vertex 0 and its opposite edge (3,4) pierces {0,1,2} at (1,1,0).
  Pairs pairs;
  EXPECT_EQ(countSelfIntersections(mesh, &pairs), 1);
  EXPECT_EQ(pairs, (Pairs{{0, 3}}));
}

TEST(SelfIntersection, RejectsInvalidInput) {
  Mesh mesh = octahedron();
  mesh.triangles.push_back({0, 1, 17});
  EXPECT_THROW(countSelfIntersections(mesh), InputError);
  Mesh inf = octahedron();
  inf.positions[2][0] = INFINITY;
  EXPECT_THROW(countSelfIntersections(inf), InputError);
}

// ---------------------------------------------------------------------------
// CGAL's Polygon_mesh_processing::self_intersections as the oracle.

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

/// The pairs CGAL finds, without its (f, f) entries for degenerate faces.
Pairs cgalPairs(const Mesh& mesh) {
  SurfaceMesh sm;
  for (const Vec3f& p : mesh.positions) sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for (const Triangle& t : mesh.triangles) {
    const auto f =
        sm.add_face(SurfaceMesh::Vertex_index(t[0]), SurfaceMesh::Vertex_index(t[1]), SurfaceMesh::Vertex_index(t[2]));
    EXPECT_NE(f, SurfaceMesh::null_face());
  }
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> found;
  CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(found));
  Pairs pairs;
  for (const auto& [f, g] : found) {
    if (f == g) continue;
    pairs.emplace_back(std::min<std::uint32_t>(f.idx(), g.idx()), std::max<std::uint32_t>(f.idx(), g.idx()));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// A grid of n x n quads whose vertices are jittered on a coarse lattice, with
/// z from a few levels only: many exactly coplanar folds, shared-vertex
/// overlaps, collinear edges and degenerate triangles.
Mesh crumpledGrid(int n, unsigned seed, int zLevels) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> jitter(-3, 3), level(0, zLevels - 1);
  Mesh mesh;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      mesh.positions.push_back(
          {float(4 * i + jitter(rng)) * 0.25f, float(4 * j + jitter(rng)) * 0.25f, float(level(rng)) * 0.5f});
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if ((i + j) % 2) {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        mesh.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return mesh;
}

TEST(SelfIntersection, MatchesCgalOnCrumpledGrids) {
  std::int64_t total = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Mesh mesh = crumpledGrid(24, seed, seed % 2 ? 1 : 3);
    Pairs ours;
    const std::int64_t count = countSelfIntersections(mesh, &ours);
    EXPECT_EQ(count, static_cast<std::int64_t>(ours.size()));
    EXPECT_EQ(ours, cgalPairs(mesh)) << "seed " << seed;
    total += count;
  }
  EXPECT_GT(total, 100);  // the grids really are crumpled
}

TEST(SelfIntersection, MatchesCgalOnANoisySphere) {
  Mesh mesh = sphere(4);
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.f, 0.06f);
  for (Vec3f& p : mesh.positions)
    for (float& c : p) c += noise(rng);
  Pairs ours;
  countSelfIntersections(mesh, &ours);
  EXPECT_FALSE(ours.empty());
  EXPECT_EQ(ours, cgalPairs(mesh));
}

TEST(SelfIntersection, MatchesCgalOnInterpenetratingSolids) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> offset(-1.5f, 1.5f);
  std::int64_t total = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Mesh mesh = sphere(2);
    const Mesh other = octahedron({offset(rng), offset(rng), offset(rng)}, 1.2f);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
    for (const Triangle& t : other.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    Pairs ours;
    total += countSelfIntersections(mesh, &ours);
    EXPECT_EQ(ours, cgalPairs(mesh)) << "trial " << trial;
  }
  EXPECT_GT(total, 0);
}

TEST(SelfIntersection, DoesNotDependOnTheThreadCount) {
  Mesh mesh = crumpledGrid(120, 11, 2);
  Pairs parallel, serial;
  const std::int64_t count = countSelfIntersections(mesh, &parallel);
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(countSelfIntersections(mesh, &serial), count);
  }
  EXPECT_GT(count, 0);
  EXPECT_EQ(parallel, serial);
}

}  // namespace
}  // namespace isovdb::mesh
