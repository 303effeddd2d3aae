// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Marching Cubes on hexahedra: accuracy on analytic fields, closed surfaces,
// Jacobian normals, faults, left-handed grids, the Emerald hole.
#include <gtest/gtest.h>

#include <set>

#include <Eigen/Geometry>

#include <tbb/global_control.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "isovdb/mesh/self_intersection.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"
#include "isovdb/split_mix.h"
#include "reservoir/grdecl_writer.h"
#include "support/test_support.h"

namespace isovdb::reservoir {
namespace {

using Eigen::Vector3d;

struct Built {
  GrdeclDeck deck;
  CornerPointGrid grid;
  CornerField field;
  HexContourResult result;
};

Built contourBox(const test::BoxGrid& box, double iso) {
  test::TempDir dir;
  test::writeFile(dir / "box.grdecl", test::boxGrdecl(box));
  Built b;
  b.deck = readGrdecl(dir / "box.grdecl");
  b.grid = buildCornerPointGrid(b.deck);
  b.field = averageToCorners(b.grid, b.deck, "PROP");
  b.result = contourHexahedra(b.grid, b.field, {.iso = iso});
  return b;
}

Vector3d at(const mesh::Mesh& m, std::size_t v) { return {m.positions[v][0], m.positions[v][1], m.positions[v][2]}; }
Vector3d normalAt(const mesh::Mesh& m, std::size_t v) { return {m.normals[v][0], m.normals[v][1], m.normals[v][2]}; }

double signedVolume(const mesh::Mesh& m) {
  double volume = 0;
  for (const auto& t : m.triangles) volume += at(m, t[0]).dot(at(m, t[1]).cross(at(m, t[2]))) / 6.0;
  return volume;
}

// A trilinear field: corner averaging of cell-centre samples and linear interpolation
// along cell edges are exact for it away from the grid border.
double trilinear(const Vector3d& p) { return 0.3 * p.x() + 0.2 * p.y() + 0.5 * p.z() + 0.02 * p.x() * p.y(); }
Vector3d trilinearGradient(const Vector3d& p) { return {0.3 + 0.02 * p.y(), 0.2 + 0.02 * p.x(), 0.5}; }

TEST(HexMarchingCubes, BoxGridMatchesAnalyticSurfaceAndGradient) {
  test::BoxGrid box{.nx = 12, .ny = 10, .nz = 8, .cell = 2.0, .origin = {1, -3, 100}};
  box.field = trilinear;
  const double iso = trilinear(Vector3d(13.3, 7.7, 108.9));  // off the nodes: no vertex on a corner
  const Built b = contourBox(box, iso);
  const mesh::Mesh& m = b.result.mesh;
  ASSERT_GT(m.triangleCount(), 100u);
  ASSERT_EQ(m.normals.size(), m.vertexCount());
  // Border nodes average one side only: measure the vertices off the border.
  const Vector3d lo = box.origin, hi = box.origin + box.cell * Vector3d(box.nx, box.ny, box.nz);
  // Central differences read one node further: normals are checked 2 cells off the border.
  auto within = [&](const Vector3d& p, double cells) {
    return ((p - lo).array() >= box.cell * cells - 1e-6).all() && ((hi - p).array() >= box.cell * cells - 1e-6).all();
  };
  double distance = 0, angleSum = 0, maxAngle = 0, allAngles = 0;
  int count = 0, normalCount = 0;
  for (std::size_t v = 0; v < m.vertexCount(); ++v) {
    const Vector3d p = at(m, v);
    const Vector3d g = trilinearGradient(p);
    const double cosine = std::clamp(-g.normalized().dot(normalAt(m, v)), -1.0, 1.0);
    const double angle = std::acos(cosine) * 180 / std::numbers::pi;
    allAngles += angle;
    if (!within(p, 1)) continue;
    distance += std::abs(trilinear(p) - iso) / g.norm();
    ++count;
    if (!within(p, 2)) continue;
    angleSum += angle;
    maxAngle = std::max(maxAngle, angle);
    ++normalCount;
  }
  ASSERT_GT(count, 50);
  ASSERT_GT(normalCount, 20);
  const double meanCells = distance / count / box.cell;
  std::cout << "box grid: " << m.triangleCount() << " triangles, mean distance " << meanCells
            << " cell; normals 2 cells inside: mean " << angleSum / normalCount << " deg, max " << maxAngle
            << " deg; all vertices: mean " << allAngles / m.vertexCount() << " deg\n";
  EXPECT_LT(meanCells, 0.02);
  EXPECT_LT(maxAngle, 5.0);
  // Triangles face their normals (towards lower values).
  int agree = 0;
  for (const auto& t : m.triangles) {
    const Vector3d face = (at(m, t[1]) - at(m, t[0])).cross(at(m, t[2]) - at(m, t[0]));
    agree += face.dot(normalAt(m, t[0]) + normalAt(m, t[1]) + normalAt(m, t[2])) > 0;
  }
  EXPECT_EQ(agree, static_cast<int>(m.triangleCount()));
  const mesh::MeshReport report = mesh::validateMesh(m);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
  EXPECT_EQ(report.components, 1);
}

TEST(HexMarchingCubes, SphereInsideTheGridIsClosedAndOutwardInBothHandedness) {
  for (bool mirror : {false, true}) {
    test::BoxGrid box{.nx = 20, .ny = 20, .nz = 20, .cell = 1.0};
    box.mirrorX = mirror;
    box.origin = mirror ? Vector3d(20, 0, 0) : Vector3d(0, 0, 0);
    const Vector3d centre(mirror ? 20 - 10.1 : 10.1, 9.8, 10.3);
    box.field = [&](const Vector3d& p) { return 6.0 - (p - centre).norm(); };
    const Built b = contourBox(box, 0.0);
    const mesh::Mesh& m = b.result.mesh;
    EXPECT_EQ(b.grid.orientation, mirror ? -1 : 1);
    const mesh::MeshReport report = mesh::validateMesh(m);
    EXPECT_TRUE(report.closed) << "mirror " << mirror;
    EXPECT_TRUE(report.manifold);
    EXPECT_EQ(report.eulerCharacteristic, 2);
    EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
    EXPECT_EQ(report.selfIntersectingPairs, 0);
    EXPECT_GT(signedVolume(m), 0) << "outward triangles, mirror " << mirror;
    int outward = 0;
    double distance = 0, maxAngle = 0;
    for (std::size_t v = 0; v < m.vertexCount(); ++v) {
      const Vector3d radial = (at(m, v) - centre).normalized();
      maxAngle =
          std::max(maxAngle, std::acos(std::clamp(normalAt(m, v).dot(radial), -1.0, 1.0)) * 180 / std::numbers::pi);
      outward += normalAt(m, v).dot(at(m, v) - centre) > 0.9 * (at(m, v) - centre).norm();
      distance += std::abs((at(m, v) - centre).norm() - 6.0);
    }
    EXPECT_EQ(outward, static_cast<int>(m.vertexCount())) << "normals within 25 deg of radial";
    EXPECT_LT(maxAngle, 5.0) << "Jacobian normals against the analytic gradient";
    std::cout << (mirror ? "left" : "right") << "-handed sphere: " << m.triangleCount()
              << " triangles, mean vertex distance " << distance / m.vertexCount() << " cell, normals at most "
              << maxAngle << " deg from radial\n";
  }
}

TEST(HexMarchingCubes, FaultSplitsTheSurfaceIntoOneSheetPerBlock) {
  test::BoxGrid box{.nx = 10, .ny = 6, .nz = 8, .cell = 1.0};
  box.faultThrow = 2.5;
  box.field = [](const Vector3d& p) { return p.z() + 0.1 * p.x(); };
  const Built b = contourBox(box, 4.2);
  const mesh::Mesh& m = b.result.mesh;
  const mesh::MeshReport report = mesh::validateMesh(m);
  std::cout << "faulted grid: " << m.triangleCount() << " triangles, " << report.components << " components\n";
  EXPECT_EQ(report.components, 2);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  for (const auto& c : report.componentReports) {
    EXPECT_EQ(c.eulerCharacteristic, 1) << "each block holds one disk";
    EXPECT_GT(c.triangles, 20);
  }
  // Without the throw the two halves weld into one sheet.
  box.faultThrow = 0;
  EXPECT_EQ(mesh::validateMesh(contourBox(box, 4.2).result.mesh).components, 1);
}

TEST(HexMarchingCubes, SheetsEndingOnAFaultDoNotCross) {
  // Folded surfaces on both sides of a fault (a throw of 3 layers): each side's sheets end
  // on the shared pillar plane along curves that cross each other there. With the vertices
  // left on the fault faces these two grids had 4 self-intersecting pairs each.
  struct Case {
    std::function<double(const Vector3d&)> field;
    double iso;
  };
  const Case cases[] = {
      {[](const Vector3d& p) { return std::sin(0.8 * p.z() + 0.7 * p.y()) + 0.1 * p.x(); }, 0.0},
      {[](const Vector3d& p) { return std::cos(p.z() / 2.0 + p.x() / 3) + 0.8 * std::sin(p.y() / 1.7); }, -0.3}};
  for (const Case& c : cases) {
    test::BoxGrid box{.nx = 12, .ny = 16, .nz = 16, .faultThrow = 3.0};
    box.field = c.field;
    const Built b = contourBox(box, c.iso);
    const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
    std::cout << "sheets at a fault: " << b.result.mesh.triangleCount() << " triangles, " << b.result.faultVertices
              << " vertices moved off the fault\n";
    EXPECT_GT(b.result.faultVertices, 0);
    EXPECT_EQ(report.selfIntersectingPairs, 0) << "iso " << c.iso;
    EXPECT_TRUE(report.manifold);
    EXPECT_EQ(report.degenerateTriangles, 0);
  }
}

/// Thin layers (3 m) under wide columns (100 m) whose pillars are shifted up or down by up
/// to `twist` metres at random: every face is a twisted bilinear patch, as in Reek, and the
/// porosity's iso-surfaces are stacked sheets a layer or two apart.
test::BoxGrid twistedLayers(std::uint64_t seed, double twist) {
  test::BoxGrid box{.nx = 16, .ny = 16, .nz = 10, .cell = 100.0, .layer = 3.0};
  const int pillarsAlongX = box.nx + 1, pillars = pillarsAlongX * (box.ny + 1);
  std::vector<double> shifts;
  SplitMix64 random(seed);
  for (int n = 0; n < pillars; ++n) shifts.push_back(twist * (2 * random.uniform() - 1));
  box.pillarShift = [shifts, pillarsAlongX](int i, int j) {
    return shifts[static_cast<std::size_t>(j * pillarsAlongX + i)];
  };
  box.field = [seed](const Vector3d& p) {
    SplitMix64 noise(seed ^ static_cast<std::uint64_t>(std::llround(p.x()) * 1000003 + std::llround(p.y()) * 1009 +
                                                       std::llround(p.z() * 10)));
    return 0.2 + 0.1 * std::sin(p.z() / 2.1 + 0.013 * p.x() + 0.017 * p.y()) + 0.04 * (noise.uniform() - 0.5);
  };
  return box;
}

TEST(HexMarchingCubes, FansStayInsideThinTwistedCells) {
  // Each loop of four or more vertices is fanned from the apex whose diagonals stay deepest
  // inside the cell, or from a centre vertex. The first apex in loop order let diagonals
  // leave these cells through their twisted faces and cross the next cell's sheet: 17, 3
  // and 9 self-intersecting pairs on these three grids.
  for (const std::uint64_t seed : {4, 5, 6}) {
    const Built b = contourBox(twistedLayers(seed, 3.0), 0.2);
    const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
    std::cout << "twisted layers, seed " << seed << ": " << b.result.mesh.triangleCount() << " triangles\n";
    ASSERT_GT(b.result.mesh.triangleCount(), 5000u) << "the iso-value no longer cuts the layers";
    EXPECT_EQ(b.grid.invertedCells, 0) << "the cells are twisted, not folded";
    EXPECT_EQ(report.selfIntersectingPairs, 0) << "seed " << seed;
    EXPECT_TRUE(report.manifold);
    EXPECT_EQ(report.degenerateTriangles, 0);
  }
}

TEST(HexMarchingCubes, FacePointsKeepTheSheetsOfTwistedLayersApart) {
  // Pillars moved up to 6 m under 3 m layers: horizontal faces bow metres off their chords,
  // and a segment between two crossings far apart on such a face ran through the next cell,
  // whose triangles it crossed (62, 32, 24 and 48 self-intersecting pairs on the first four
  // grids, 9, 9, 7 and 12 on the last four with 3 m moves). Those segments now run through
  // face points on the patches, shared by the two cells of each face.
  const std::pair<std::uint64_t, double> grids[] = {{8, 6.0}, {9, 6.0}, {10, 6.0}, {18, 6.0},
                                                    {3, 3.0}, {8, 3.0}, {10, 3.0}, {14, 3.0}};
  for (const auto& [seed, twist] : grids) {
    const Built b = contourBox(twistedLayers(seed, twist), 0.2);
    const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
    EXPECT_GT(b.result.facePoints, 400) << "seed " << seed << ": the faces are no longer seen as twisted";
    EXPECT_EQ(report.selfIntersectingPairs, 0) << "seed " << seed << ", twist " << twist;
    EXPECT_TRUE(report.manifold) << "a face point was not welded between its two cells";
    EXPECT_EQ(report.degenerateTriangles, 0);
  }
  // A flat layer cake has no face points: its mesh is the one it always was.
  test::BoxGrid flat{.nx = 12, .ny = 12, .nz = 8, .cell = 100.0, .layer = 3.0};
  flat.field = [](const Vector3d& p) { return 0.2 + 0.1 * std::sin(p.z() / 2.1 + 0.013 * p.x()); };
  EXPECT_EQ(contourBox(flat, 0.2).result.facePoints, 0);
}

TEST(HexMarchingCubes, LayersThatPinchOutShareTheirPoints) {
  // 3 m layers under 100 m columns: layer 3 thins out westwards to nothing at i <= 5, layer
  // 2 along a diagonal, and layer 5 has no thickness anywhere. Where a layer's top and
  // bottom meet on a pillar they are one point (grouped around each node, they were two,
  // each with its own average): the cells on both sides of a pinch-out share its surface,
  // and a layer of zero thickness makes none. Before, these grids had 53-60 crossing pairs.
  for (const double twist : {0.0, 1.0}) {
    test::BoxGrid box{.nx = 14, .ny = 12, .nz = 8, .cell = 100.0};
    SplitMix64 random(7);
    std::vector<double> shifts;
    for (int n = 0; n < (box.nx + 1) * (box.ny + 1); ++n) shifts.push_back(twist * (2 * random.uniform() - 1));
    box.pillarShift = [shifts, box](int i, int j) { return shifts[static_cast<std::size_t>(j * (box.nx + 1) + i)]; };
    box.thickness = [](int i, int j, int k) {
      if (k == 3) return std::max(0.0, 3.0 * (i - 5) / 6.0);
      if (k == 2) return std::max(0.0, 0.5 * (i + j - 12));
      return k == 5 ? 0.0 : 3.0;
    };
    box.field = [](const Vector3d& p) { return 0.2 + 0.1 * std::sin(p.z() / 2.1 + 0.013 * p.x() + 0.011 * p.y()); };
    test::TempDir dir;
    test::writeFile(dir / "pinch.grdecl", test::boxGrdecl(box));
    const GrdeclDeck deck = readGrdecl(dir / "pinch.grdecl");
    const CornerPointGrid grid = buildCornerPointGrid(deck);
    ASSERT_GT(grid.pinchedCells, 20);
    const CornerField field = averageToCorners(grid, deck, "PROP");
    for (const double iso : {0.15, 0.2, 0.25}) {
      const HexContourResult r = contourHexahedra(grid, field, {.iso = iso, .triangleCells = true});
      const mesh::MeshReport report = mesh::validateMesh(r.mesh);
      ASSERT_GT(r.mesh.triangleCount(), 500u) << "iso " << iso << " no longer cuts the layers";
      EXPECT_EQ(report.selfIntersectingPairs, 0) << "twist " << twist << ", iso " << iso;
      EXPECT_TRUE(report.manifold) << "twist " << twist << ", iso " << iso;
      EXPECT_EQ(report.degenerateTriangles, 0) << "twist " << twist << ", iso " << iso;
      const auto inFlatLayer = std::count_if(r.triangleCells.begin(), r.triangleCells.end(), [&](std::uint32_t cell) {
        return cell / static_cast<std::size_t>(box.nx * box.ny) == 5;
      });
      EXPECT_EQ(inFlatLayer, 0) << "the layer of no thickness made triangles";
    }
  }
}

TEST(HexMarchingCubes, CellsThatMeetAtAnEdgeOnlyKeepTheirOwnVertices) {
  // Active columns in a checkerboard: each column's sheet is a square whose corners lie on
  // the vertical edges it shares with its diagonal neighbours only (the cells beside are
  // inactive). One vertex per edge joined the squares at non-manifold vertices (Emerald,
  // whose hole and faults leave such edges, had two to three at every iso-value of a smooth
  // property). Each cell's crossing there is now its own, moved into the cell.
  test::BoxGrid box{.nx = 4, .ny = 4, .nz = 3};
  box.active = [](int i, int j, int) { return (i + j) % 2 == 0; };
  box.field = [](const Vector3d& p) { return p.z() + 0.05 * p.x(); };
  const Built b = contourBox(box, 1.6);
  const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.selfIntersectingPairs, 0) << "the squares touch";
  EXPECT_EQ(report.components, 8) << "one square per active column";
  for (const auto& c : report.componentReports) EXPECT_EQ(c.eulerCharacteristic, 1);
  // At 1.06 the crossings on the edges of pillars i = 1 lie a hundredth of the way from
  // their lower ends, where other crossings are not moved off faults; a lone crossing is,
  // or the two cells' vertices would touch at one place.
  const mesh::MeshReport nearCorner = mesh::validateMesh(contourBox(box, 1.06).result.mesh);
  EXPECT_EQ(nearCorner.selfIntersectingPairs, 0);
  EXPECT_EQ(nearCorner.nonManifoldVertices, 0);
  EXPECT_EQ(nearCorner.components, 8);
  // In a grid whose cells all share their edges, no crossing is lone: the same mesh.
  box.active = {};
  const Built full = contourBox(box, 1.6);
  EXPECT_EQ(mesh::validateMesh(full.result.mesh).components, 1);
  EXPECT_EQ(full.result.mesh.vertexCount(), 25u) << "one vertex per vertical edge of the 4 x 4 columns";
}

TEST(HexMarchingCubes, CellsThatShareAnEdgeButNotTheFaceKeepTheirOwnVertices) {
  // Random depths at every cell corner (2 x 2 x 3 cells, most of them folded): cells on two
  // sides of a face that share one of its edges and nothing else of it. Their sheets met at
  // the one vertex on that edge (a non-manifold vertex in these two decks, and in 171 of 200
  // such decks); the cells that hold an edge now weld its vertex only within groups joined
  // by whole shared faces.
  const std::string zcorn[] = {
      "0 0 -3 3 3 0 -3 -3 -3 3 0 -3 0 0 0 0 -1 2 2 -1 2 2 2 2 2 2 2 -1 2 5 2 2 2 5 2 -1 2 -1 2 2 2 5 5 2 5 5 2 2 "
      "4 4 1 1 1 7 4 7 4 4 4 1 7 4 7 4 4 4 7 4 4 4 1 1 4 4 4 1 4 4 4 7 3 3 6 3 6 6 3 6 6 6 6 9 3 6 6 9",
      "0 0 -3 3 0 -3 0 -3 0 3 0 3 -3 0 -3 0 5 2 2 5 2 -1 2 5 2 2 -1 -1 2 2 2 2 2 2 2 2 2 2 5 2 -1 2 5 2 2 2 -1 2 "
      "4 1 4 1 4 4 4 7 4 4 7 7 4 1 4 1 4 7 1 7 4 7 1 7 1 4 4 1 4 7 4 4 6 9 3 6 6 3 9 3 6 6 6 6 6 6 3 6"};
  const std::string poro[] = {"4 2 4 6 9 2 5 9 0 5 0 7", "5 4 2 1 2 4 7 2 0 1 9 8"};
  for (int deck = 0; deck < 2; ++deck) {
    test::TempDir dir;
    test::writeFile(dir / "random.grdecl",
                    "SPECGRID\n 2 2 3 1 F /\nCOORD\n0 0 0 0 0 10\n10 0 0 10 0 10\n20 0 0 20 0 10\n"
                    "0 10 0 0 10 10\n10 10 0 10 10 10\n20 10 0 20 10 10\n0 20 0 0 20 10\n10 20 0 10 20 10\n"
                    "20 20 0 20 20 10\n/\nZCORN\n" +
                        zcorn[deck] + " /\nPORO\n" + poro[deck] + " /\n");
    const GrdeclDeck grdecl = readGrdecl(dir / "random.grdecl");
    const CornerPointGrid grid = buildCornerPointGrid(grdecl);
    const HexContourResult r = contourHexahedra(grid, averageToCorners(grid, grdecl, "PORO"), {.iso = 4.5});
    const mesh::MeshReport report = mesh::validateMesh(r.mesh);
    ASSERT_GT(r.mesh.triangleCount(), 5u) << "deck " << deck;
    EXPECT_EQ(report.nonManifoldVertices, 0) << "deck " << deck;
    EXPECT_EQ(report.nonManifoldEdges, 0) << "deck " << deck;
    EXPECT_EQ(report.degenerateTriangles, 0) << "deck " << deck;
  }
}

TEST(HexMarchingCubes, OutputIsTheSameWhateverTheThreadCount) {
  // 40 x 40 x 12 cells: several blocks of cells, each thread appending to its own arrays,
  // welded across the blocks' borders and a fault; ambiguous faces on the way.
  test::BoxGrid box{.nx = 40, .ny = 40, .nz = 12, .faultThrow = 0.5};
  box.field = [](const Vector3d& p) { return std::cos(0.9 * p.x()) * std::cos(0.9 * p.y()) + 0.05 * p.z(); };
  const auto contourWith = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    return contourBox(box, 0.21);
  };
  const Built one = contourWith(1), four = contourWith(4);
  const mesh::Mesh& m = one.result.mesh;
  ASSERT_GT(one.grid.cellCount(), 16000u) << "the grid no longer spans several blocks";
  EXPECT_EQ(m.positions, four.result.mesh.positions);
  EXPECT_EQ(m.triangles, four.result.mesh.triangles);
  EXPECT_EQ(m.normals, four.result.mesh.normals);
  EXPECT_GT(one.result.ambiguousFaces, 0);
  const mesh::MeshReport report = mesh::validateMesh(m);
  EXPECT_TRUE(report.manifold) << "ambiguous faces decided alike by both cells";
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.degenerateTriangles, 0);
  std::set<std::array<float, 3>> distinct(m.positions.begin(), m.positions.end());
  EXPECT_EQ(distinct.size(), m.vertexCount()) << "a vertex made by cells of two blocks was not welded";
}

TEST(HexMarchingCubes, BinaryIndicatorAtOneHalfHasNoZeroAreaTriangles) {
  // A 0/1 facies ball: corners where as many cells are in as out average to exactly 0.5.
  test::BoxGrid box{.nx = 14, .ny = 14, .nz = 14};
  box.field = [](const Vector3d& p) { return (p - Vector3d(7, 7, 7)).norm() < 4.5 ? 1.0 : 0.0; };
  const Built b = contourBox(box, 0.5);
  const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
  EXPECT_EQ(report.degenerateTriangles, 0);
  EXPECT_TRUE(report.closed);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.eulerCharacteristic, 2);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
}

TEST(HexMarchingCubes, CornersAtTheIsoValueOfAUtmGridStayManifold) {
  // The 0/1 ball at 0.5 where easting and northing are UTM-sized (float steps of 0.5 m)
  // and layers thin: a vertex a little way along a vertical edge moves only in depth,
  // where floats are fine. Judging the offset by the largest coordinate shared the
  // corner's vertex among its edges instead (Reek: 115 non-manifold edges).
  test::BoxGrid box{.nx = 14, .ny = 14, .nz = 14, .cell = 100.0, .layer = 2.0, .origin = {460000, 593000, 1600}};
  box.field = [&box](const Vector3d& p) {
    const Vector3d q = (p - box.origin).cwiseQuotient(Vector3d(box.cell, box.cell, box.layer)) - Vector3d(7, 7, 7);
    return q.norm() < 4.5 ? 1.0 : 0.0;
  };
  const Built b = contourBox(box, 0.5);
  const mesh::MeshReport report = mesh::validateMesh(b.result.mesh);
  ASSERT_GT(b.result.mesh.triangleCount(), 0u);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.degenerateTriangles, 0);
}

TEST(HexMarchingCubes, CornersAtTheIsoValueNeitherFoldNorCollapse) {
  // ResInsight's regular27cell deck: PORO 0.4 beside 0.5 averages to 0.45 (within
  // rounding) at corners, two of them on some faces. Vertices at those corners made
  // 20 self-intersecting pairs (surfaces of neighbouring cells folded over each other).
  const GrdeclDeck deck = readGrdecl(test::dataDir() / "reservoir/fault_test/regular27cell.DATA");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, "PORO");
  const auto atIso = std::count_if(field.pointValues.begin(), field.pointValues.end(),
                                   [](double v) { return std::abs(v - 0.45) < 1e-12; });
  ASSERT_GT(atIso, 0) << "the deck no longer has corners at the iso-value";
  const HexContourResult r = contourHexahedra(grid, field, {.iso = 0.45});
  const mesh::MeshReport report = mesh::validateMesh(r.mesh);
  ASSERT_GT(r.mesh.triangleCount(), 0u);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
  EXPECT_EQ(report.degenerateTriangles, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  std::set<std::array<float, 3>> distinct;
  for (const auto& p : r.mesh.positions) distinct.insert({p[0], p[1], p[2]});
  EXPECT_EQ(distinct.size(), r.mesh.positions.size()) << "vertices at the same place, not welded";
}

TEST(HexMarchingCubes, OpposedTrianglesInAFaceCancel) {
  // Reek PORO 0.22: a corner at the iso-value on a short pinched edge becomes the grid
  // point's own vertex, and the cells on both sides of a face each made the triangle
  // through it and the face's two crossings, wound opposite ways: three edges of four
  // triangles each (two non-manifold edges in the validator's count).
  const auto dir = test::sharedDataDir() / "reservoir/reek";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
  // With pinch-outs joined (GridOptions::joinPinchOuts) that edge has no length and the
  // deck no longer makes the pair; the cancellation stays for edges just above the tolerance.
  const GrdeclDeck deck = readGrdecl({dir / "reek_sim_grid.grdecl", dir / "reek_sim_poro.grdecl"});
  const CornerPointGrid grid = buildCornerPointGrid(deck, {.joinPinchOuts = false});
  const HexContourResult r = contourHexahedra(grid, averageToCorners(grid, deck, "PORO"), {.iso = 0.22});
  ASSERT_GE(r.cancelledTwins, 1) << "the deck no longer makes the opposed pair at 0.22";
  const mesh::MeshReport report = mesh::validateMesh(r.mesh);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
  std::set<std::array<std::uint32_t, 3>> faces;
  for (auto t : r.mesh.triangles) {
    std::sort(t.begin(), t.end());
    EXPECT_TRUE(faces.insert(t).second) << "two triangles on the same three vertices";
  }
}

TEST(HexMarchingCubes, TriangleCellsNameTheCellThatMadeEachTriangle) {
  // A ball in a box grid: each triangle's vertices lie in (or on) the cell named for it.
  test::BoxGrid box{.nx = 10, .ny = 10, .nz = 10};
  box.field = [](const Vector3d& p) { return (p - Vector3d(5, 5, 5)).norm(); };
  test::TempDir dir;
  test::writeFile(dir / "box.grdecl", test::boxGrdecl(box));
  const GrdeclDeck deck = readGrdecl(dir / "box.grdecl");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, "PROP");
  const HexContourResult with = contourHexahedra(grid, field, {.iso = 3.2, .triangleCells = true});
  const HexContourResult without = contourHexahedra(grid, field, {.iso = 3.2});
  EXPECT_TRUE(without.triangleCells.empty());
  EXPECT_EQ(with.mesh.triangles, without.mesh.triangles);
  ASSERT_EQ(with.triangleCells.size(), with.mesh.triangleCount());
  EXPECT_EQ(std::count(grid.cellShape.begin(), grid.cellShape.end(), 0), static_cast<long>(grid.cellCount()));
  for (std::size_t t = 0; t < with.mesh.triangleCount(); ++t) {
    const auto& corners = grid.corners[with.triangleCells[t]];
    Vector3d lo = corners[0], hi = corners[0];
    for (const Vector3d& c : corners) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    for (const std::uint32_t v : with.mesh.triangles[t]) {
      const Vector3d p = at(with.mesh, v);
      EXPECT_TRUE((p.array() >= lo.array() - 1e-4).all() && (p.array() <= hi.array() + 1e-4).all())
          << "triangle " << t << " vertex " << p.transpose() << " outside its cell";
    }
  }
}

TEST(HexMarchingCubes, Spe9PermeabilityIsManifold) {
  // PERMX at 100 mD crosses faces with four crossings whose fans, from a vertex on
  // that face, used to put one edge in four triangles (two per cell).
  const GrdeclDeck deck = readGrdecl(test::dataDir() / "reservoir/spe9/SPE9_CP.DATA");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const HexContourResult r = contourHexahedra(grid, averageToCorners(grid, deck, "PERMX"), {.iso = 100});
  const mesh::MeshReport report = mesh::validateMesh(r.mesh);
  std::cout << "SPE9 PERMX 100: " << r.mesh.triangleCount() << " triangles, " << r.ambiguousFaces
            << " ambiguous faces\n";
  EXPECT_GT(r.ambiguousFaces, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_TRUE(report.manifold);
  EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
}

TEST(HexMarchingCubes, CrossingsNearACornerStayOnTheirFaultFace) {
  // Reek PORO 0.1, cell (27, 48, 11): two crossings 0.3 % of their edges from one corner,
  // 0.7 m apart, both on fault faces. Moved off the faults (1.5 m, in different directions)
  // they crossed the line to the loop's far vertex and the fan folded over itself; at 0.18
  // the same put a 2 m triangle through the next cell's sheet. Crossings within
  // kMaxCornerOffset of a corner now stay where they are, like those held off a corner.
  const auto dir = test::sharedDataDir() / "reservoir/reek";
  if (!std::filesystem::exists(dir / "reek_sim_grid.grdecl")) GTEST_SKIP() << "no " << dir;
  const GrdeclDeck deck = readGrdecl(std::vector{dir / "reek_sim_grid.grdecl", dir / "reek_sim_poro.grdecl"});
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, "PORO");
  for (const double iso : {0.1, 0.18}) {
    const HexContourResult r = contourHexahedra(grid, field, {.iso = iso, .triangleCells = true});
    ASSERT_GT(r.faultVertices, 500) << "the grid's faults no longer move crossings";
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    mesh::countSelfIntersections(r.mesh, &pairs);
    int awayFromPinchedCells = 0;
    for (const auto& [a, b] : pairs)
      awayFromPinchedCells +=
          !((grid.cellShape[r.triangleCells[a]] | grid.cellShape[r.triangleCells[b]]) & CornerPointGrid::kPinchedCell);
    EXPECT_EQ(awayFromPinchedCells, 0) << "PORO " << iso;
  }
}

TEST(HexMarchingCubes, EmeraldSurfaceStopsAtTheInactiveHole) {
  const auto path = test::sharedDataDir() / "reservoir/emerald/eme_small_w_hole_grid_params.grdecl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const GrdeclDeck deck = readGrdecl(path);
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, "FACIES");
  const HexContourResult r = contourHexahedra(grid, field, {.iso = 0.5});
  const mesh::Mesh& m = r.mesh;
  const mesh::MeshReport report = mesh::validateMesh(m);
  std::cout << "Emerald FACIES 0.5: " << m.triangleCount() << " triangles, " << report.boundaryEdges
            << " boundary edges, " << report.nonManifoldEdges << " non-manifold edges\n";
  ASSERT_GT(m.triangleCount(), 1000u);  // 2,214 when measured
  EXPECT_GT(report.boundaryEdges, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.degenerateTriangles, 0);
  std::cout << "Emerald FACIES 0.5: " << report.selfIntersectingPairs << " self-intersecting pairs, "
            << grid.invertedCells << " inverted cells\n";
  // Every vertex lies on a point of a usable cell: nothing reaches into the hole.
  // (Vertices are on edges of usable cells by construction; check the triangles'
  // faces agree with the Jacobian normals in this left-handed grid.)
  EXPECT_EQ(grid.orientation, 1);
  int agree = 0;
  for (const auto& t : m.triangles) {
    const Vector3d face = (at(m, t[1]) - at(m, t[0])).cross(at(m, t[2]) - at(m, t[0]));
    agree += face.dot(normalAt(m, t[0]) + normalAt(m, t[1]) + normalAt(m, t[2])) >= 0;
  }
  EXPECT_GT(agree, 0.95 * static_cast<double>(m.triangleCount()));
}

}  // namespace
}  // namespace isovdb::reservoir
