// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/regular_contour.h: manifold Dual Marching Cubes on
// regular octrees, checked with the mesh validator (closed, manifold, Euler),
// exhaustively on pairs of cell configurations and on generated volumes.
#include "isovdb/contour/regular_contour.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include "generators/shapes.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/octree/build.h"
#include "isovdb/octree/surface_cells.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"

namespace isovdb::contour {
namespace {

using cell::MetaCellSamples;

struct ContourRun {
  mesh::Mesh mesh;
  mesh::MeshReport report;
  RegularContourStats stats;
};

/// Regular octree down to 1-voxel cells, then manifold DMC, then validation.
ContourRun contour(const cell::MetaCellSamples& samples, float iso = 0.0f, bool manifoldFix = true,
                   bool parallel = true, bool selfIntersections = false, int minDepth = 0,
                   RegularTopology topology = RegularTopology::Voxels) {
  const cell::ContourSettings settings{
      .method = cell::ContourMethod::Regular, .iso = iso, .manifoldFix = manifoldFix, .topology = topology};
  octree::OctreeOptions treeOptions;
  treeOptions.minDepth = minDepth;
  treeOptions.finestCellSize = 1;
  treeOptions.parallel = parallel;
  const octree::LinearOctree tree = octree::buildOctree(samples, settings, treeOptions);
  ContourRun run;
  run.mesh = contourRegular(samples, tree, settings, &run.stats);
  run.report = mesh::validateMesh(run.mesh, {.selfIntersections = selfIntersections});
  return run;
}

std::string describe(const ContourRun& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "V=%lld T=%lld closed=%d manifold=%d nmE=%lld nmV=%lld boundary=%lld chi=%lld",
                static_cast<long long>(r.report.referencedVertices), static_cast<long long>(r.report.triangles),
                int(r.report.closed), int(r.report.manifold), static_cast<long long>(r.report.nonManifoldEdges),
                static_cast<long long>(r.report.nonManifoldVertices), static_cast<long long>(r.report.boundaryEdges),
                static_cast<long long>(r.report.eulerCharacteristic));
  return buf;
}

bool good(const ContourRun& r) {
  return r.report.closed && r.report.manifold && r.report.boundaryEdges == 0 &&
         r.report.inconsistentlyOrientedEdges == 0;
}

/// Signed volume of a closed mesh (positive when the triangles face outward).
double signedVolume(const mesh::Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const auto& a = m.positions[t[0]];
    const auto& b = m.positions[t[1]];
    const auto& c = m.positions[t[2]];
    v += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
          double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
          double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
         6.0;
  }
  return v;
}

// --- exhaustive pairs of configurations ------------------------------------

/// A 4^3 meta-cell whose 27 interior samples (offsets 1..3) are the corners of
/// a 2x2x2 block of cells; every other sample is outside, so the surface stays
/// off the meta-cell boundary and the mesh must be closed.
struct Block {
  std::array<float, 27> interior{};
  float& at(int i, int j, int k) { return interior[static_cast<std::size_t>((k * 3 + j) * 3 + i)]; }
  cell::MetaCellSamples samples() const {
    return cell::makeMetaCellSamples(4, {0, 0, 0}, [&](int x, int y, int z) {
      if (x < 1 || y < 1 || z < 1 || x > 3 || y > 3 || z > 3) return 1.0f;
      return interior[static_cast<std::size_t>(((z - 1) * 3 + (y - 1)) * 3 + (x - 1))];
    });
  }
};

/// Value of a sample of the given phase: random magnitude so vertices move around.
float phaseValue(bool inside, std::mt19937& rng) {
  std::uniform_real_distribution<float> mag(0.1f, 1.0f);
  return inside ? -mag(rng) : mag(rng);
}

/// Both readings of ambiguous cells (voxel_dmc.h, dmc_table.h).
class RegularTopologies : public ::testing::TestWithParam<RegularTopology> {};

TEST_P(RegularTopologies, ExhaustivePairsOfConfigurationsAcrossEverySharedFace) {
  const RegularTopology topology = GetParam();
  std::mt19937 rng(12345);
  std::int64_t meshes = 0, pairsWithAmbiguousFace = 0, fixesUsed = 0, brokenWithoutFix = 0, failures = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int configA = 0; configA < 256; ++configA) {
      for (int far = 0; far < 16; ++far) {
        // Cell A at block cell (0,0,0), cell B its neighbour along `axis`; B's corners
        // on the shared face come from A, its 4 far corners from `far`.
        auto cornerPos = [&](int cell, int c) {
          std::array<int, 3> p{c & 1, (c >> 1) & 1, (c >> 2) & 1};
          p[static_cast<std::size_t>(axis)] += cell;
          return p;
        };
        std::array<int, 27> phase{};
        phase.fill(-1);  // unset
        for (int c = 0; c < 8; ++c) {
          const auto p = cornerPos(0, c);
          phase[static_cast<std::size_t>((p[2] * 3 + p[1]) * 3 + p[0])] = (configA >> c) & 1;
        }
        int farBit = 0;
        for (int c = 0; c < 8; ++c) {
          if (((c >> axis) & 1) == 0) continue;
          const auto p = cornerPos(1, c);
          phase[static_cast<std::size_t>((p[2] * 3 + p[1]) * 3 + p[0])] = (far >> farBit++) & 1;
        }
        // Is the shared face ambiguous?
        std::uint8_t faceBits = 0;
        int n = 0;
        for (int c = 0; c < 8; ++c)
          if ((c >> axis) & 1) faceBits = static_cast<std::uint8_t>(faceBits | (((configA >> c) & 1) << n++));
        const bool ambiguous = faceBits == 0b1001 || faceBits == 0b0110;
        pairsWithAmbiguousFace += ambiguous;
        // Fills of the 15 other corners: all outside, all inside, and random ones
        // when the shared face is ambiguous.
        const int fills = ambiguous ? 6 : 2;
        for (int fill = 0; fill < fills; ++fill) {
          Block block;
          for (int idx = 0; idx < 27; ++idx) {
            bool in;
            if (phase[static_cast<std::size_t>(idx)] >= 0)
              in = phase[static_cast<std::size_t>(idx)] == 1;
            else
              in = fill == 0 ? false : fill == 1 ? true : (rng() & 1) != 0;
            block.interior[static_cast<std::size_t>(idx)] = phaseValue(in, rng);
          }
          const cell::MetaCellSamples samples = block.samples();
          const ContourRun r = contour(samples, 0.0f, true, false, false, 0, topology);
          ++meshes;
          fixesUsed += r.stats.manifoldFixes;
          if (!good(r)) {
            if (++failures <= 5)
              ADD_FAILURE() << "axis " << axis << " configA " << configA << " far " << far << " fill " << fill << ": "
                            << describe(r);
          }
          if (ambiguous && fill >= 2) {
            const ContourRun off = contour(samples, 0.0f, false, false, false, 0, topology);
            brokenWithoutFix += !off.report.manifold;
          }
        }
      }
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(fixesUsed, 0);
  EXPECT_GT(brokenWithoutFix, 0);
  std::printf("[exhaustive] meshes=%lld ambiguousPairs=%lld manifoldFixes=%lld nonManifoldWithoutFix=%lld\n",
              static_cast<long long>(meshes), static_cast<long long>(pairsWithAmbiguousFace),
              static_cast<long long>(fixesUsed), static_cast<long long>(brokenWithoutFix));
}

TEST_P(RegularTopologies, RandomSignFieldsWithExactIsoSamplesStayClosedAndManifold) {
  // Integer samples in {-1, 0, 1} at iso 0: many samples equal the isovalue
  // (counted inside) and every configuration pattern occurs.
  const RegularTopology topology = GetParam();
  std::mt19937 rng(7);
  std::int64_t fixes = 0, brokenWithoutFix = 0, triangles = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::uniform_int_distribution<int> d(-1, 1);
    const cell::MetaCellSamples samples = cell::makeMetaCellSamples(16, {0, 0, 0}, [&](int x, int y, int z) {
      if (x < 1 || y < 1 || z < 1 || x > 15 || y > 15 || z > 15) return 1.0f;
      return float(d(rng));
    });
    const ContourRun r = contour(samples, 0.0f, true, true, false, 0, topology);
    EXPECT_TRUE(good(r)) << "trial " << trial << ": " << describe(r);
    fixes += r.stats.manifoldFixes;
    triangles += r.report.triangles;
    const ContourRun off = contour(samples, 0.0f, false, true, false, 0, topology);
    brokenWithoutFix += !off.report.manifold;
  }
  EXPECT_GT(fixes, 0);
  EXPECT_GT(brokenWithoutFix, 0);
  std::printf("[random] triangles=%lld manifoldFixes=%lld nonManifoldWithoutFix=%d/40\n",
              static_cast<long long>(triangles), static_cast<long long>(fixes), int(brokenWithoutFix));
}

INSTANTIATE_TEST_SUITE_P(Readings, RegularTopologies, ::testing::Values(RegularTopology::Voxels, RegularTopology::Mdmc),
                         [](const auto& info) { return info.param == RegularTopology::Voxels ? "voxels" : "mdmc"; });

// --- analytic SDFs -------------------------------------------------------

double sphereSdf(double x, double y, double z) {
  return std::sqrt((x - 31.3) * (x - 31.3) + (y - 32.6) * (y - 32.6) + (z - 30.9) * (z - 30.9)) - 20.0;
}

double torusSdf(double x, double y, double z) {
  const double px = x - 32.4, py = y - 31.7, pz = z - 32.2;
  const double q = std::sqrt(px * px + py * py) - 18.0;
  return std::sqrt(q * q + pz * pz) - 7.0;
}

double meanAbsDistance(const mesh::Mesh& m, double (*sdf)(double, double, double)) {
  double sum = 0;
  for (const auto& p : m.positions) sum += std::abs(sdf(p[0], p[1], p[2]));
  return m.positions.empty() ? 1e9 : sum / double(m.positions.size());
}

struct AnalyticCase {
  const char* name;
  double (*sdf)(double, double, double);
  int euler;
};

class RegularContourAnalytic : public ::testing::TestWithParam<AnalyticCase> {};

TEST_P(RegularContourAnalytic, ClosedManifoldRightEulerAndOnTheZeroLevel) {
  const AnalyticCase& c = GetParam();
  const cell::MetaCellSamples samples =
      cell::makeMetaCellSamples(64, {0, 0, 0}, [&](int x, int y, int z) { return c.sdf(x, y, z); });
  const ContourRun r = contour(samples, 0.0f, true, true, true);
  EXPECT_TRUE(good(r)) << describe(r);
  EXPECT_EQ(r.report.eulerCharacteristic, 2 * c.euler) << describe(r);  // surface chi = 2 * solid chi
  EXPECT_EQ(r.report.selfIntersectingPairs, 0);
  EXPECT_GT(signedVolume(r.mesh), 0.0);  // outward orientation
  const double mean = meanAbsDistance(r.mesh, c.sdf);
  EXPECT_LT(mean, 0.2);
  // Every vertex lies in the cell of its group's edges: within one voxel of the surface.
  double worst = 0;
  for (const auto& p : r.mesh.positions) worst = std::max(worst, std::abs(c.sdf(p[0], p[1], p[2])));
  EXPECT_LT(worst, std::sqrt(3.0));
  std::printf("[%s] triangles=%lld vertices=%lld chi=%lld meanDist=%.4f maxDist=%.4f fixes=%lld volume=%.1f\n", c.name,
              static_cast<long long>(r.report.triangles), static_cast<long long>(r.report.referencedVertices),
              static_cast<long long>(r.report.eulerCharacteristic), mean, worst,
              static_cast<long long>(r.stats.manifoldFixes), signedVolume(r.mesh));
}

INSTANTIATE_TEST_SUITE_P(Shapes, RegularContourAnalytic,
                         ::testing::Values(AnalyticCase{"sphere", &sphereSdf, 1}, AnalyticCase{"torus", &torusSdf, 0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(RegularContour, IsoOnIntegerSamplesCountsThemInside) {
  // A sphere SDF rounded to integers: a whole shell of samples equals the isovalue.
  for (const float iso : {0.0f, 2.0f}) {
    const cell::MetaCellSamples samples = cell::makeMetaCellSamples(
        64, {0, 0, 0}, [](int x, int y, int z) { return float(std::round(sphereSdf(x, y, z))); });
    const ContourRun r = contour(samples, iso);
    EXPECT_TRUE(good(r)) << "iso " << iso << ": " << describe(r);
    EXPECT_EQ(r.report.eulerCharacteristic, 2) << "iso " << iso;
  }
}

TEST(RegularContour, DeterministicForOneAndEightThreads) {
  const cell::MetaCellSamples samples =
      cell::makeMetaCellSamples(64, {-3, 5, 2}, [](int x, int y, int z) { return torusSdf(x + 3, y - 5, z - 2); });
  auto once = [&](int threads) {
    tbb::task_arena arena(threads);
    mesh::Mesh m;
    arena.execute([&] { m = contour(samples, 0.0f, true, true, false, /*minDepth=*/2).mesh; });
    return m;
  };
  const mesh::Mesh a = once(1), b = once(8);
  ASSERT_FALSE(a.empty());
  // The same mesh as from a tree with another minimum depth (surface leaves are all 1-voxel).
  const mesh::Mesh c = contour(samples).mesh;
  EXPECT_EQ(a.triangles, c.triangles);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  // Positions are global index coordinates: the torus centre moved with the origin.
  double cx = 0;
  for (const auto& p : a.positions) cx += p[0];
  EXPECT_NEAR(cx / double(a.positions.size()), 32.4 - 3.0, 0.5);
}

TEST(RegularContour, BoundaryEdgesAreSkippedAndMismatchedIsoThrows) {
  // A plane crossing the whole meta-cell: its edges on the boundary are skipped -> open mesh.
  const cell::MetaCellSamples samples =
      cell::makeMetaCellSamples(8, {0, 0, 0}, [](int x, int, int) { return float(x) - 3.5f; });
  const ContourRun r = contour(samples);
  EXPECT_FALSE(r.report.closed);
  EXPECT_TRUE(r.report.manifold);
  EXPECT_GT(r.report.triangles, 0);
  // A tree built at another isovalue is rejected.
  const octree::LinearOctree tree = octree::buildOctree(samples, {.method = cell::ContourMethod::Regular, .iso = 0.0f},
                                                        {.minDepth = 0, .finestCellSize = 1});
  EXPECT_THROW(contourRegular(samples, tree, {.method = cell::ContourMethod::Regular, .iso = 1.0f}), InputError);
}

TEST_P(RegularTopologies, SurfaceCellTreeGivesTheSameMeshAndSeamAsTheFullTree) {
  // extract contours regular mode on octree::surfaceCellTree (the cells the surface
  // crosses): the mesh, its vertex order and the seam must be the full tree's. Random
  // signs with samples on the isovalue (every configuration, Wenger's fix, tubes) reach
  // the meta-cell's boundary, so seam cells and boundary edges are compared too.
  const RegularTopology topology = GetParam();
  const cell::ContourSettings settings{.method = cell::ContourMethod::Regular, .topology = topology};
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> d(-1, 1);
  for (int trial = 0; trial < 6; ++trial) {
    const cell::MetaCellSamples samples =
        cell::makeMetaCellSamples(32, {32, -64, 0}, [&](int, int, int) { return float(d(rng)); });
    RegularContourStats fullStats, surfaceStats;
    const MetaCellMesh full =
        contourRegularMetaCell(samples, octree::buildOctree(samples, settings), settings, &fullStats);
    const MetaCellMesh surface =
        contourRegularMetaCell(samples, octree::surfaceCellTree(samples, settings.iso), settings, &surfaceStats);
    ASSERT_GT(full.mesh.triangles.size(), 0u);
    EXPECT_EQ(full.mesh.positions, surface.mesh.positions) << "trial " << trial;
    EXPECT_EQ(full.mesh.triangles, surface.mesh.triangles) << "trial " << trial;
    ASSERT_EQ(full.seam.cells.size(), surface.seam.cells.size());
    for (std::size_t i = 0; i < full.seam.cells.size(); ++i) {
      EXPECT_EQ(full.seam.cells[i].key, surface.seam.cells[i].key);
      EXPECT_EQ(full.seam.cells[i].vertices, surface.seam.cells[i].vertices);
    }
    EXPECT_EQ(fullStats.boundaryEdges, surfaceStats.boundaryEdges);
    EXPECT_EQ(fullStats.manifoldFixes, surfaceStats.manifoldFixes);
  }
}

// --- generated volumes (binary masks -> distance field) --------------------

class RegularContourGenerated : public ::testing::TestWithParam<samples::ShapeKind> {};

cell::MetaCellSamples shapeSamples(samples::ShapeKind kind, int size) {
  auto stream = samples::makeShapeStream(kind, {.size = size});
  const volume::Volume sdf = volume::distanceField(volume::ingestMask(*stream, {}));
  auto acc = volume::fieldGrid(sdf).getConstAccessor();
  // One whole-volume meta-cell padded by at least 8 voxels on every side.
  int s = 1;
  while (s < size + 16) s *= 2;
  return cell::makeMetaCellSamples(s, {-8, -8, -8},
                                   [&](int x, int y, int z) { return acc.getValue(openvdb::Coord(x, y, z)); });
}

TEST_P(RegularContourGenerated, ClosedManifoldWithTheObjectsEulerCharacteristic) {
  const samples::ShapeKind kind = GetParam();
  const cell::MetaCellSamples samples = shapeSamples(kind, 64);
  const ContourRun r = contour(samples);
  EXPECT_TRUE(good(r)) << describe(r);
  EXPECT_EQ(r.report.nonManifoldEdges, 0);
  EXPECT_EQ(r.report.nonManifoldVertices, 0);
  EXPECT_EQ(r.report.eulerCharacteristic, 2 * samples::knownEulerCharacteristic(kind)) << describe(r);
  const ContourRun off = contour(samples, 0.0f, false);
  std::printf("[%s] triangles=%lld chi=%lld fixes=%lld | fix off: nmE=%lld nmV=%lld\n",
              std::string(samples::shapeName(kind)).c_str(), static_cast<long long>(r.report.triangles),
              static_cast<long long>(r.report.eulerCharacteristic), static_cast<long long>(r.stats.manifoldFixes),
              static_cast<long long>(off.report.nonManifoldEdges),
              static_cast<long long>(off.report.nonManifoldVertices));
}

INSTANTIATE_TEST_SUITE_P(Shapes, RegularContourGenerated, ::testing::ValuesIn(samples::shapesOfKnownTopology()),
                         [](const auto& info) {
                           std::string name(samples::shapeName(info.param));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace isovdb::contour

namespace isovdb::contour {
namespace {

TEST(RegularContour, FixOffShowsNonManifoldOnNoisyGeneratedVolumes) {
  // The generated shapes' distance fields and binary masks are smooth enough to
  // contain no pair of adjacent 2B-I / 3B-I cells (fix off: 0 non-manifold
  // elements, printed by the test above). Sub-voxel noise on the same fields,
  // as in scanned data, creates such pairs: without the fix the mesh is
  // non-manifold, with it closed and manifold.
  std::int64_t brokenWithoutFix = 0;
  for (const samples::ShapeKind kind : samples::shapesOfKnownTopology()) {
    cell::MetaCellSamples samples = shapeSamples(kind, 64);
    std::mt19937 rng(static_cast<unsigned>(kind) + 1);
    std::uniform_real_distribution<float> noise(-0.6f, 0.6f);
    for (float& v : samples.values) v += noise(rng);
    const ContourRun r = contour(samples);
    EXPECT_TRUE(good(r)) << samples::shapeName(kind) << ": " << describe(r);
    const ContourRun off = contour(samples, 0.0f, false);
    if (!off.report.manifold) ++brokenWithoutFix;
    std::printf("[%s noisy] triangles=%lld chi=%lld fixes=%lld | fix off: nmE=%lld nmV=%lld\n",
                std::string(samples::shapeName(kind)).c_str(), static_cast<long long>(r.report.triangles),
                static_cast<long long>(r.report.eulerCharacteristic), static_cast<long long>(r.stats.manifoldFixes),
                static_cast<long long>(off.report.nonManifoldEdges),
                static_cast<long long>(off.report.nonManifoldVertices));
  }
  EXPECT_GT(brokenWithoutFix, 0);
}

}  // namespace
}  // namespace isovdb::contour
