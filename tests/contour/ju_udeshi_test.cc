// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/ju_udeshi.h: face points, the envelope test and
// the fan / trivial triangulations of one minimal edge (Ju & Udeshi 2006;
// paper 000, section 4.2.3.2).
#include "isovdb/contour/ju_udeshi.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <vector>

namespace isovdb::contour {
namespace {

/// Regular configuration: unit edge along z from (0,0,0) to (0,0,1), four unit
/// cells around it in cyclic order (-,-), (+,-), (+,+), (-,+) (quadrants 0, 1, 3, 2).
EdgeEnvelope regularEnvelope(const std::array<Vec3d, 4>& cells) {
  EdgeEnvelope env;
  env.edgeStart = {0, 0, 0};
  env.edgeEnd = {0, 0, 1};
  env.cellCount = 4;
  env.cellPoints = cells;
  return env;
}

/// Minimal faces between consecutive cells of regularEnvelope: x = 0 or y = 0 planes.
std::array<MinimalFace, 4> regularFaces() {
  return {MinimalFace{.axis = 0, .coordinate = 0, .min = {0, -1, 0}, .size = 1},    // cells 0 | 1 (y < 0)
          MinimalFace{.axis = 1, .coordinate = 0, .min = {0, 0, 0}, .size = 1},     // cells 1 | 2 (x > 0)
          MinimalFace{.axis = 0, .coordinate = 0, .min = {-1, 0, 0}, .size = 1},    // cells 2 | 3 (y > 0)
          MinimalFace{.axis = 1, .coordinate = 0, .min = {-1, -1, 0}, .size = 1}};  // cells 3 | 0 (x < 0)
}

std::array<bool, 4> fillFacePoints(EdgeEnvelope& env) {
  const auto faces = regularFaces();
  std::array<bool, 4> crossed{};
  for (int i = 0; i < 4; ++i) {
    const FacePoint fp = computeFacePoint(env.cellPoints[i], env.cellPoints[(i + 1) % 4], faces[i]);
    env.facePoints[i] = fp.point;
    crossed[i] = fp.crossed;
  }
  return crossed;
}

TEST(JuUdeshi, FacePointIsTheCrossingWhenInsideTheFace) {
  const MinimalFace face{.axis = 0, .coordinate = 0, .min = {0, 0, 0}, .size = 1};
  const FacePoint in = computeFacePoint({-0.5, 0.2, 0.4}, {0.5, 0.6, 0.6}, face);
  EXPECT_TRUE(in.crossed);
  EXPECT_NEAR(in.point[0], 0.0, 1e-12);
  EXPECT_NEAR(in.point[1], 0.4, 1e-12);
  EXPECT_NEAR(in.point[2], 0.5, 1e-12);
  // The segment crosses the plane outside the face: clamped inside, not crossed.
  const FacePoint out = computeFacePoint({-0.5, 1.4, 0.4}, {0.5, 1.6, 0.6}, face);
  EXPECT_FALSE(out.crossed);
  EXPECT_GT(out.point[1], 0.0);
  EXPECT_LT(out.point[1], 1.0);
  EXPECT_EQ(out.point[0], 0.0);
}

TEST(JuUdeshi, AMissedFaceFarFromItsSegmentTakesTheRimPointNearestTheSegment) {
  // Two cell points on either side of the face x = 0 (face [0,1]^2 in y, z), their segment
  // almost parallel to it: it crosses the plane at (0, 1.42, 0.33), beyond the face's edge
  // y = 1. Clamped, that crossing became (0, 0.999, 0.325), 0.35 from the segment; the rim
  // point nearest the segment is (0, 0.999, 0.95), 0.05 from its end a.
  const MinimalFace face{.axis = 0, .coordinate = 0, .min = {0, 0, 0}, .size = 1};
  const Vec3d a{-0.05, 1.0, 0.95}, b{0.01, 1.5, 0.2};
  const FacePoint fp = computeFacePoint(a, b, face);
  EXPECT_FALSE(fp.crossed);
  EXPECT_EQ(fp.point[0], 0.0);
  for (int axis = 1; axis < 3; ++axis) {
    EXPECT_GT(fp.point[axis], 0.0);
    EXPECT_LT(fp.point[axis], 1.0);
  }
  // Its distance to the segment is the face's distance to it (up to the 1e-3 margin).
  const auto segmentDistance = [&](const Vec3d& q) {
    double best = 1e9;
    for (int i = 0; i <= 2000; ++i) {
      const double t = i / 2000.0;
      const double dx = a[0] + t * (b[0] - a[0]) - q[0], dy = a[1] + t * (b[1] - a[1]) - q[1],
                   dz = a[2] + t * (b[2] - a[2]) - q[2];
      best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return best;
  };
  double faceDistance = 1e9;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) faceDistance = std::min(faceDistance, segmentDistance({0.0, i / 100.0, j / 100.0}));
  EXPECT_LT(segmentDistance(fp.point), faceDistance + 2e-3);
  EXPECT_LT(segmentDistance(fp.point), 0.06) << "the clamped crossing lay 0.35 away";
  // A segment that misses the face close by keeps the clamp of its crossing.
  const FacePoint near = computeFacePoint({-0.5, 1.05, 0.4}, {0.5, 1.15, 0.6}, face);
  EXPECT_FALSE(near.crossed);
  EXPECT_NEAR(near.point[1], 1.0 - 1e-3, 1e-12);
  EXPECT_NEAR(near.point[2], 0.5, 1e-12);
}

TEST(JuUdeshi, FlatQuadAcrossTheEdgeKeepsTheTrivialTriangulation) {
  // A plane z = 0.5 cut: the four vertices at the cell centres' height 0.5.
  EdgeEnvelope env = regularEnvelope({Vec3d{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}});
  const auto crossed = fillFacePoints(env);
  for (bool c : crossed) EXPECT_TRUE(c);
  EXPECT_TRUE(triangleInEnvelope(env, env.cellPoints[0], env.cellPoints[1], env.cellPoints[2]));
  const EdgeTriangulation how = chooseTriangulation(env, crossed);
  EXPECT_FALSE(how.fan);
  std::vector<std::array<int, 3>> tris;
  triangulateEdge(4, crossed, how, tris);
  EXPECT_EQ(tris.size(), 2u);
}

/// Number of times the segment e0 e1 (x = y = 0, 0 < z < 1) pierces triangle (a, b, c).
int piercings(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  // 2D barycentric test of the origin in the projected triangle, then the height there.
  const double d = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  if (d == 0) return 0;
  const double u = ((0 - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (0 - a[1])) / d;
  const double v = ((b[0] - a[0]) * (0 - a[1]) - (0 - a[0]) * (b[1] - a[1])) / d;
  if (u < 0 || v < 0 || u + v > 1) return 0;
  const double z = a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]);
  return z > 0 && z < 1 ? 1 : 0;
}

TEST(JuUdeshi, RandomQuadsTrivialOnlyWhenTheSurfaceCrossesTheEdgeOnce) {
  // Random vertices in the four cells: whenever the trivial triangulation is
  // kept, its two triangles cross the edge exactly once; some configurations
  // with every face crossed still need the fan (the envelope test matters).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  int trivial = 0, fanWithCrossedFaces = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::array<Vec3d, 4> cells;
    const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i) cells[i] = {sx[i] * unit(rng), sy[i] * unit(rng), unit(rng)};
    EdgeEnvelope env = regularEnvelope(cells);
    const auto crossed = fillFacePoints(env);
    const EdgeTriangulation how = chooseTriangulation(env, crossed);
    const bool allCrossed = crossed[0] && crossed[1] && crossed[2] && crossed[3];
    if (how.fan) {
      fanWithCrossedFaces += allCrossed ? 1 : 0;
      continue;
    }
    ASSERT_TRUE(allCrossed);
    ++trivial;
    const auto& c = env.cellPoints;
    const int n = how.apex == 0 ? piercings(c[0], c[1], c[2]) + piercings(c[0], c[2], c[3])
                                : piercings(c[1], c[2], c[3]) + piercings(c[1], c[3], c[0]);
    EXPECT_EQ(n, 1) << "trial " << trial;
  }
  std::printf("random quads: %d trivial, %d fans with all faces crossed\n", trivial, fanWithCrossedFaces);
  EXPECT_GT(trivial, 100);
  EXPECT_GT(fanWithCrossedFaces, 0);
}

TEST(JuUdeshi, UncrossedFaceRoutesThePolygonThroughTheFacePoint) {
  // Cell 2's vertex is far up the x = 0 face's side: the segment c2 c3 misses face 2.
  EdgeEnvelope env = regularEnvelope({Vec3d{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}});
  auto crossed = fillFacePoints(env);
  crossed[2] = false;
  const std::vector<int> polygon = edgePolygon(4, crossed);
  EXPECT_EQ(polygon, (std::vector<int>{0, 1, 2, kFaceVertex + 2, 3}));
  const EdgeTriangulation how = chooseTriangulation(env, crossed);
  std::vector<std::array<int, 3>> tris;
  triangulateEdge(4, crossed, how, tris);
  EXPECT_EQ(tris.size(), how.fan ? 5u : 3u);
  // The polygon side c2 -> c3 is never used: the path goes c2 -> f2 -> c3.
  for (const auto& t : tris)
    for (int s = 0; s < 3; ++s) EXPECT_FALSE(t[s] == 2 && t[(s + 1) % 3] == 3);
}

TEST(JuUdeshi, TriangleFarOutsideIsRejected) {
  EdgeEnvelope env = regularEnvelope({Vec3d{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}});
  fillFacePoints(env);
  // A triangle that crosses the edge line above e1 (z = 1.5).
  EXPECT_FALSE(triangleInEnvelope(env, {-0.5, -0.5, 1.5}, {0.5, -0.5, 1.5}, {0.0, 0.8, 1.5}));
  // One that reaches the edge's end point is rejected too (margin).
  EXPECT_FALSE(triangleInEnvelope(env, {-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.0, 0.8, 0.0}));
}

/// regularEnvelope's cells and face points turned so the edge runs along `axis` (a cyclic
/// permutation of x, y, z keeps the handedness), scaled by `size` and moved to `at`.
EdgeEnvelope movedEnvelope(const EdgeEnvelope& env, int axis, double size, const Vec3d& at) {
  const auto move = [&](const Vec3d& p) {
    Vec3d q{};
    for (int a = 0; a < 3; ++a) q[(a + axis + 1) % 3] = at[(a + axis + 1) % 3] + size * p[a];
    return q;
  };
  EdgeEnvelope out = env;
  out.edgeStart = move(env.edgeStart);
  out.edgeEnd = move(env.edgeEnd);
  for (int i = 0; i < 4; ++i) {
    out.cellPoints[i] = move(env.cellPoints[i]);
    out.facePoints[i] = move(env.facePoints[i]);
  }
  return out;
}

/// The full envelope test's answers against the test across the edge's.
struct AcrossTally {
  int keptByFull = 0, keptByBoth = 0, wrong = 0;
  void add(bool full, bool fast) {
    keptByFull += full ? 1 : 0;
    keptByBoth += full && fast ? 1 : 0;
    wrong += fast && !full ? 1 : 0;
  }
  /// Never a polygon the full test refuses, and at least `share` of those it keeps.
  void expect(const char* what, double share) const {
    std::printf("%s: the full test keeps %d, the test across the edge %d of them\n", what, keptByFull, keptByBoth);
    EXPECT_EQ(wrong, 0) << what;
    EXPECT_GT(keptByBoth, share * keptByFull) << what;
  }
};

TEST(JuUdeshi, QuadClearlyInsideOnlyWhereTheEnvelopeTestKeepsBothTriangles) {
  // Random quads with every face crossed, along each axis and at two sizes: whenever the
  // test across the edge accepts a diagonal, the full envelope test keeps both triangles;
  // and it answers most of the quads the full test keeps (what it is for).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  int quads = 0;
  AcrossTally tally;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Vec3d, 4> cells;
    const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    // A quarter of the quads hug the end e1 (their faces still crossed below 0.999).
    const bool nearEnd = trial % 4 == 0;
    for (int i = 0; i < 4; ++i)
      cells[i] = {sx[i] * unit(rng), sy[i] * unit(rng), nearEnd ? 0.998 + 0.0015 * unit(rng) : unit(rng)};
    EdgeEnvelope base = regularEnvelope(cells);
    const auto crossed = fillFacePoints(base);
    if (!(crossed[0] && crossed[1] && crossed[2] && crossed[3])) continue;
    const int axis = trial % 3;
    const double size = trial % 2 ? 1.0 : 4.0;
    const EdgeEnvelope env = movedEnvelope(base, axis, size, {100.0 + trial % 7, 50.0, 12.0});
    ++quads;
    for (int apex = 0; apex < 2; ++apex) {
      const auto& c = env.cellPoints;
      const bool full = triangleInEnvelope(env, c[apex], c[apex + 1], c[apex + 2]) &&
                        triangleInEnvelope(env, c[apex], c[apex + 2], c[(apex + 3) % 4]);
      tally.add(full, clearlyInsideEnvelope(env, apex));
    }
  }
  EXPECT_GT(quads, 5000);
  tally.expect("random quads' diagonals", 0.9);
}

/// Three cells around the unit edge x = y = 0, 0 <= z <= 1: two unit cells below y = 0
/// and a cell of size 2 above it (x in [-1, 1], y in [0, 2], z in [0, 2]), with their
/// face points. @return whether every face is crossed.
bool threeCellEnvelope(const std::array<Vec3d, 3>& cells, EdgeEnvelope& env) {
  const std::array<MinimalFace, 3> faces{
      MinimalFace{.axis = 0, .coordinate = 0, .min = {0, -1, 0}, .size = 1},   // unit cells 0 | 1
      MinimalFace{.axis = 1, .coordinate = 0, .min = {0, 0, 0}, .size = 1},    // cell 1 | the large cell
      MinimalFace{.axis = 1, .coordinate = 0, .min = {-1, 0, 0}, .size = 1}};  // the large cell | cell 0
  env = EdgeEnvelope{};
  env.edgeStart = {0, 0, 0};
  env.edgeEnd = {0, 0, 1};
  env.cellCount = 3;
  bool allCrossed = true;
  for (int i = 0; i < 3; ++i) {
    env.cellPoints[i] = cells[i];
    const FacePoint fp = computeFacePoint(cells[i], cells[(i + 1) % 3], faces[i]);
    env.facePoints[i] = fp.point;
    allCrossed = allCrossed && fp.crossed;
  }
  return allCrossed;
}

TEST(JuUdeshi, TriangleClearlyInsideOnlyWhereTheEnvelopeTestKeepsIt) {
  // Random triangles with every face crossed: whenever the test across the edge accepts
  // one, the full envelope test keeps it; it answers almost all of them (the edge line
  // then crosses the triangle between the two face points on its plane y = 0, inside
  // the face's height).
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  int triangles = 0;
  AcrossTally tally;
  for (int trial = 0; trial < 20000; ++trial) {
    EdgeEnvelope env;
    const std::array<Vec3d, 3> cells{Vec3d{-unit(rng), -unit(rng), unit(rng)}, Vec3d{unit(rng), -unit(rng), unit(rng)},
                                     Vec3d{2.0 * unit(rng) - 1.0, 2.0 * unit(rng), 2.0 * unit(rng)}};
    if (!threeCellEnvelope(cells, env)) continue;
    ++triangles;
    tally.add(triangleInEnvelope(env, env.cellPoints[0], env.cellPoints[1], env.cellPoints[2]),
              clearlyInsideEnvelope(env, 0));
  }
  EXPECT_GT(triangles, 3000);
  tally.expect("random three-cell triangles", 0.97);
  // Left to the full test: a cell point within 10^-3 of the edge line, and a face point
  // off its face's plane through the edge (not a face of the three cells).
  EdgeEnvelope env;
  ASSERT_TRUE(threeCellEnvelope({Vec3d{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.1, 0.6, 0.5}}, env));
  EXPECT_TRUE(clearlyInsideEnvelope(env, 0));
  EdgeEnvelope nearLine = env;
  nearLine.cellPoints[2] = {0.0002, 0.0005, 0.5};
  EXPECT_FALSE(clearlyInsideEnvelope(nearLine, 0));
  EdgeEnvelope offFace = env;
  offFace.facePoints[1][1] = 0.01;
  EXPECT_FALSE(clearlyInsideEnvelope(offFace, 0));
}

TEST(JuUdeshi, QuadClearlyInsideRejectsAQuadThroughTheEdgeEnd) {
  // A flat quad across the edge is inside (a diagonal through the edge line itself is
  // left to the full test); lifted to the height of e1, or with a cell vertex pulled onto
  // the edge line, it is not (or not clearly).
  const EdgeEnvelope square =
      regularEnvelope({Vec3d{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}});
  EdgeEnvelope flat = square;
  flat.cellPoints[1] = {0.6, -0.3, 0.5};
  flat.cellPoints[2] = {0.4, 0.6, 0.5};
  fillFacePoints(flat);
  EXPECT_TRUE(clearlyInsideEnvelope(flat, 0));
  EXPECT_TRUE(clearlyInsideEnvelope(flat, 1));
  EdgeEnvelope symmetric = square;
  fillFacePoints(symmetric);
  EXPECT_FALSE(clearlyInsideEnvelope(symmetric, 0));
  EdgeEnvelope high = flat;
  for (auto& c : high.cellPoints) c[2] = 0.99995;
  fillFacePoints(high);
  EXPECT_FALSE(clearlyInsideEnvelope(high, 0));
  // c1 low and near the edge line, the others high: whatever the test across the edge
  // accepts, the full test keeps.
  EdgeEnvelope folded =
      regularEnvelope({Vec3d{-0.5, -0.5, 0.9}, {0.05, -0.05, 0.1}, {0.5, 0.5, 0.9}, {-0.5, 0.5, 0.5}});
  fillFacePoints(folded);
  for (int apex = 0; apex < 2; ++apex)
    if (clearlyInsideEnvelope(folded, apex)) {
      const auto& c = folded.cellPoints;
      EXPECT_TRUE(triangleInEnvelope(folded, c[apex], c[apex + 1], c[apex + 2]) &&
                  triangleInEnvelope(folded, c[apex], c[apex + 2], c[(apex + 3) % 4]));
    }
  EdgeEnvelope onLine = flat;
  onLine.cellPoints[1] = {0.0, 0.0, 0.5};
  EXPECT_FALSE(clearlyInsideEnvelope(onLine, 0));
}

TEST(JuUdeshi, FullFanHasTwoTrianglesPerCellAroundTheEdge) {
  std::vector<std::array<int, 3>> tris;
  const EdgeTriangulation fan{true, 0};
  triangulateEdge(4, {false, false, false, false}, fan, tris);
  EXPECT_EQ(tris.size(), 8u);
  triangulateEdge(3, {false, false, false, true}, fan, tris);
  ASSERT_EQ(tris.size(), 6u);
  // Every triangle uses v_e and a (v_c, v_f) or (v_f, v_c) side, each once, in polygon order.
  std::set<std::pair<int, int>> sides;
  for (const auto& t : tris) {
    EXPECT_EQ(t[0], kEdgeVertex);
    EXPECT_TRUE((t[1] < kFaceVertex) != (t[2] < kFaceVertex));
    EXPECT_TRUE(sides.insert({t[1], t[2]}).second);
  }
  EXPECT_TRUE(sides.count({0, kFaceVertex + 0}) && sides.count({kFaceVertex + 0, 1}) &&
              sides.count({kFaceVertex + 2, 0}));
  // With crossed faces the fan triangles of a face merge into (v_e, c_i, c_{i+1}).
  triangulateEdge(4, {true, true, true, true}, fan, tris);
  EXPECT_EQ(tris.size(), 4u);
}

}  // namespace
}  // namespace isovdb::contour
