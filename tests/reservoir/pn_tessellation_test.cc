// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// PN triangles with envelope normals: Table 4.1, crack-free refinement, accuracy on a sphere.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "isovdb/mesh/validate.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"
#include "isovdb/reservoir/pn_tessellation.h"
#include "isovdb/reservoir/pn_triangle.h"
#include "reservoir/grdecl_writer.h"
#include "support/test_support.h"

namespace isovdb::reservoir {
namespace {

using Eigen::Vector3d;

TEST(PnTessellation, ExponentialRuleReproducesTable41) {
  // Paper 003 Table 4.1 (k = 20): t -> e(t'').
  const std::vector<std::pair<double, double>> table = {{-1.0, 48.607}, {-0.5, 16.111}, {0.0, 6.839},
                                                        {0.5, 2.984},   {0.75, 1.849},  {1.0, 1.000}};
  for (const auto& [t, e] : table) EXPECT_NEAR(edgeSubdivisions(t, 20, FactorRule::Exponential), e, 2e-3) << t;
  EXPECT_EQ(edgeFactor(Vector3d(1, 0, 0), Vector3d(-1, 0, 0), 20, FactorRule::Exponential), 20);
  EXPECT_EQ(edgeFactor(Vector3d(1, 0, 0), Vector3d(1, 0, 0), 20, FactorRule::Exponential), 1);
  EXPECT_EQ(edgeFactor(Vector3d(1, 0, 0), Vector3d(0, 1, 0), 20, FactorRule::Linear), 10);
}

TEST(PnTessellation, PatchInterpolatesCornersAndEnvelopeNormalIsTheCornerNormal) {
  const std::array<Vector3d, 3> p{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  const std::array<Vector3d, 3> n{Vector3d(-0.3, -0.3, 1).normalized(), Vector3d(0.3, 0, 1).normalized(),
                                  Vector3d(0, 0.3, 1).normalized()};
  const PnTriangle patch(p, n);
  std::array<Vector3d, 3> q;
  for (int c = 0; c < 3; ++c) q[c] = p[c] + 0.2 * n[c];
  const PnTriangle inflated(q, n);
  EXPECT_LT((patch.position(0, 1, 0) - p[1]).norm(), 1e-12);
  EXPECT_LT((envelopeNormal(patch, inflated, 0, 0, 1) - n[2]).norm(), 1e-9);
  EXPECT_LT((patch.quadraticNormal(1, 0, 0) - n[0]).norm(), 1e-12);
  // Curved: the centre bulges along the normals' mean.
  EXPECT_GT(patch.position(1 / 3.0, 1 / 3.0, 1 / 3.0).z(), 0.0);
}

// Mean distance to the sphere over points spread on each triangle (barycentric grid, area-weighted).
double meanDistance(const mesh::Mesh& m, const Vector3d& centre, double radius) {
  double sum = 0, area = 0;
  const int s = 4;
  for (const auto& t : m.triangles) {
    const Vector3d a(m.positions[t[0]][0], m.positions[t[0]][1], m.positions[t[0]][2]);
    const Vector3d b(m.positions[t[1]][0], m.positions[t[1]][1], m.positions[t[1]][2]);
    const Vector3d c(m.positions[t[2]][0], m.positions[t[2]][1], m.positions[t[2]][2]);
    const double ta = 0.5 * (b - a).cross(c - a).norm();
    double local = 0;
    int count = 0;
    for (int i = 0; i <= s; ++i)
      for (int j = 0; i + j <= s; ++j, ++count)
        local += std::abs((a + (b - a) * i / s + (c - a) * j / s - centre).norm() - radius);
    sum += ta * local / count;
    area += ta;
  }
  return sum / area;
}

TEST(PnTessellation, SphereOnACoarseGridStaysClosedAndGetsCloser) {
  // A sphere of radius 7 sampled at the centres of a 20^3 grid of unit cells (a distance field).
  // Averaging cell values to the corners lowers them by about h^2/(4R); the iso-value
  // takes that known bias out so the comparison is between the triangles.
  const double radius = 7.0;
  const Vector3d centre(10.2, 9.9, 10.1);
  test::BoxGrid box{.nx = 20, .ny = 20, .nz = 20};
  box.field = [&](const Vector3d& p) { return radius - (p - centre).norm(); };
  test::TempDir dir;
  test::writeFile(dir / "sphere.grdecl", test::boxGrdecl(box));
  const GrdeclDeck deck = readGrdecl(dir / "sphere.grdecl");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, "PROP");
  const mesh::Mesh flat = contourHexahedra(grid, field, {.iso = -1.0 / (4 * radius)}).mesh;
  ASSERT_TRUE(mesh::validateMesh(flat, {.selfIntersections = false}).closed);
  const double flatDistance = meanDistance(flat, centre, radius);
  for (FactorRule rule : {FactorRule::Exponential, FactorRule::Linear}) {
    const TessellationResult pn = tessellatePn(flat, {.maxFactor = 4, .rule = rule});
    const mesh::MeshReport report = mesh::validateMesh(pn.mesh);
    EXPECT_TRUE(report.closed) << "no cracks";
    EXPECT_TRUE(report.manifold);
    EXPECT_EQ(report.eulerCharacteristic, 2);
    EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
    EXPECT_EQ(report.selfIntersectingPairs, 0);
    const double pnDistance = meanDistance(pn.mesh, centre, radius);
    std::cout << (rule == FactorRule::Linear ? "linear" : "exponential") << " rule: " << flat.triangleCount() << " -> "
              << pn.mesh.triangleCount() << " triangles, mean factor " << pn.meanFactor << "; mean distance flat "
              << flatDistance << ", PN " << pnDistance << " (ratio " << flatDistance / pnDistance << ")\n";
    if (rule == FactorRule::Exponential) {
      EXPECT_GE(flatDistance / pnDistance, 2.0);
    }
    // Envelope normals stay radial.
    double worst = 1;
    for (std::size_t v = 0; v < pn.mesh.vertexCount(); ++v) {
      const Vector3d p(pn.mesh.positions[v][0], pn.mesh.positions[v][1], pn.mesh.positions[v][2]);
      const Vector3d n(pn.mesh.normals[v][0], pn.mesh.normals[v][1], pn.mesh.normals[v][2]);
      worst = std::min(worst, n.dot((p - centre).normalized()));
    }
    EXPECT_GT(worst, std::cos(10 * 3.14159265 / 180));
  }
}

TEST(PnTessellation, MaximumFactorOneKeepsTheMesh) {
  mesh::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}};
  const TessellationResult r = tessellatePn(m, {.maxFactor = 1});
  EXPECT_EQ(r.mesh.triangles, m.triangles);
  EXPECT_EQ(r.mesh.positions, m.positions);
  m.normals = {{-0.6f, 0, 0.8f}, {0.6f, 0, 0.8f}, {0, 0.6f, 0.8f}};
  EXPECT_GT(tessellatePn(m, {.maxFactor = 8}).mesh.triangleCount(), 1u);
}

/// Two squares 0.05 apart, each of two triangles: the lower one's normals lean out of a
/// point below it (its patches bulge up), the upper one's out of a point above (they bulge
/// down), as on thin layers whose sheets curve towards each other.
mesh::Mesh facingSheets() {
  mesh::Mesh m;
  const auto sheet = [&](float z, float lean, bool flip) {
    const auto first = static_cast<std::uint32_t>(m.positions.size());
    for (const auto& [x, y] : {std::pair{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}}) {
      m.positions.push_back({x, y, z});
      const Vector3d n = Vector3d(x - 0.5, y - 0.5, lean).normalized();
      m.normals.push_back({static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())});
    }
    if (flip)
      m.triangles.insert(m.triangles.end(), {{first, first + 2, first + 1}, {first, first + 3, first + 2}});
    else
      m.triangles.insert(m.triangles.end(), {{first, first + 1, first + 2}, {first, first + 2, first + 3}});
  };
  sheet(0.0f, 0.5f, false);
  sheet(0.05f, -0.5f, true);
  return m;
}

TEST(PnTessellation, PatchesThatCrossKeepTheirEdgesStraight) {
  const mesh::Mesh flat = facingSheets();
  ASSERT_EQ(mesh::validateMesh(flat).selfIntersectingPairs, 0);
  const TessellationResult curved = tessellatePn(flat, {.maxFactor = 4, .straightenCrossings = false});
  ASSERT_GT(mesh::validateMesh(curved.mesh).selfIntersectingPairs, 0) << "the bulges no longer meet";
  const TessellationResult r = tessellatePn(flat, {.maxFactor = 4});
  EXPECT_GT(r.pairsBefore, 0);
  EXPECT_EQ(r.pairsAfter, 0);
  EXPECT_GT(r.straightEdges, 0);
  const mesh::MeshReport report = mesh::validateMesh(r.mesh);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.components, 2);
  EXPECT_EQ(report.boundaryEdges, mesh::validateMesh(curved.mesh).boundaryEdges)
      << "straight edges are cut as the curved ones were: no crack between patches";
}

}  // namespace
}  // namespace isovdb::reservoir
