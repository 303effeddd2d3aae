// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Our octree methods end to end through the pipeline (mask -> SDF -> one padded
// meta-cell -> octree -> contour), each mesh checked by the validator.
#include <gtest/gtest.h>

#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "generators/shapes.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/volume/digital_topology.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "support/analytic_sdf.h"
#include "support/mesh_distance.h"
#include "support/test_support.h"
#include "support/vector_slice_stream.h"

namespace isovdb::pipeline {
namespace {

volume::Volume shapeSdf(samples::ShapeKind kind, int size) {
  auto stream = samples::makeShapeStream(kind, {.size = size});
  return toContourable(volume::ingestMask(*stream, {}), {});
}

/// Mean |SDF| at the mesh vertices (trilinear), in voxels: distance to the zero level.
double meanDistanceToZeroLevel(const mesh::Mesh& mesh, const volume::Volume& sdf) {
  openvdb::tools::GridSampler<volume::FieldGrid, openvdb::tools::BoxSampler> sampler(volume::fieldGrid(sdf));
  double sum = 0;
  for (const auto& p : mesh.positions) sum += std::abs(sampler.isSample(openvdb::Vec3d(p[0], p[1], p[2])));
  return mesh.positions.empty() ? 0 : sum / static_cast<double>(mesh.positions.size());
}

mesh::Mesh contour(const volume::Volume& sdf, ContourMethod method, bool manifoldFix = true) {
  return contourWithOctree(sdf, {.method = method, .manifoldFix = manifoldFix});
}

class OctreeMethods : public ::testing::TestWithParam<samples::ShapeKind> {};

TEST_P(OctreeMethods, RegularIsClosedManifoldWithTheObjectsTopologyAndOnTheSurface) {
  const volume::Volume sdf = shapeSdf(GetParam(), 64);
  const mesh::Mesh mesh = contour(sdf, ContourMethod::Regular);
  const mesh::MeshReport report = mesh::validateMesh(mesh, {.selfIntersections = false});
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
  EXPECT_EQ(report.eulerCharacteristic, 2 * samples::knownEulerCharacteristic(GetParam()));
  EXPECT_LT(meanDistanceToZeroLevel(mesh, sdf), 0.2);
}

TEST_P(OctreeMethods, AdaptiveIsClosedIntersectionFreeAndCoarser) {
  const volume::Volume sdf = shapeSdf(GetParam(), 64);
  const mesh::Mesh adaptive = contour(sdf, ContourMethod::Adaptive);
  const mesh::MeshReport report = mesh::validateMesh(adaptive);
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
  EXPECT_EQ(report.eulerCharacteristic, 2 * samples::knownEulerCharacteristic(GetParam()));
  EXPECT_LT(meanDistanceToZeroLevel(adaptive, sdf), 0.5);
  // At 64^3 the gyroid's channels are 10 voxels wide and curved everywhere:
  // 2.4x there, 4-12x on the other shapes (QEF tolerance 0.15).
  const std::size_t factor = GetParam() == samples::ShapeKind::GyroidSlab ? 2 : 3;
  EXPECT_LT(factor * adaptive.triangleCount(), contour(sdf, ContourMethod::Regular).triangleCount());
}

INSTANTIATE_TEST_SUITE_P(Shapes, OctreeMethods,
                         ::testing::Values(samples::ShapeKind::Sphere, samples::ShapeKind::Torus,
                                           samples::ShapeKind::Genus2, samples::ShapeKind::GyroidSlab,
                                           samples::ShapeKind::SaltDome),
                         [](const auto& info) {
                           std::string name(samples::shapeName(info.param));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// --sharp-features end to end: 16-voxel meta-cells cut the rims, whose seams are
// stitched from the cells' vertices; the mesh follows both rims within 0.1 voxel
// (without the option its coarse rim leaves cut them by about 0.2 voxel).
TEST(OctreeMethodsSharpFeatures, CylinderKeepsItsRimsAcrossMetaCells) {
  const std::array<double, 3> c{32.41, 31.63, 32.27};
  const double r = 14.3, hh = 11.2;
  const volume::Volume sdf =
      test::levelSetVolume(64, [&](const std::array<double, 3>& p) { return test::cylinderSdf(p, c, r, hh); });
  for (const bool sharp : {false, true}) {
    SCOPED_TRACE(sharp ? "sharp features" : "Prewitt normals");
    const cell::ContourSettings settings{.method = ContourMethod::Adaptive, .sharpFeatures = sharp};
    Statistics stats;
    const mesh::Mesh mesh = contourWithOctree(sdf, settings, {.maxCellSize = 8}, /*metaCellSize=*/16, nullptr, &stats);
    EXPECT_GT(stats["stitch"]["edges"].get<std::int64_t>(), 0);  // the rims cross seams
    const mesh::MeshReport report = mesh::validateMesh(mesh);
    EXPECT_TRUE(report.closed);
    EXPECT_EQ(report.selfIntersectingPairs, 0);
    EXPECT_EQ(report.eulerCharacteristic, 2);
    double rimToSurface = 0;
    for (const double side : {-1.0, 1.0})
      for (int i = 0; i < 360; ++i) {
        const double a = 2 * M_PI * i / 360;
        rimToSurface =
            std::max(rimToSurface,
                     test::distanceToMesh(mesh, {c[0] + r * std::cos(a), c[1] + r * std::sin(a), c[2] + side * hh}));
      }
    std::printf("cylinder, 16-voxel meta-cells%s: %zu triangles, rim-to-surface %.4f voxel\n",
                sharp ? ", sharp features" : "", mesh.triangles.size(), rimToSurface);
    if (sharp) {
      EXPECT_LT(rimToSurface, 0.1);
    } else {
      EXPECT_GT(rimToSurface, 0.1);
    }
  }
}

mesh::Mesh contourRegular(const volume::Volume& sdf, cell::RegularTopology topology, bool manifoldFix = true) {
  return contourWithOctree(sdf, {.method = ContourMethod::Regular, .manifoldFix = manifoldFix, .topology = topology});
}

volume::Volume frogSkeletonMask() {
  InputOptions input;
  input.rule.labels = {13};
  return loadVolume(test::dataDir() / "frog" / "frogtissue.mhd", input);
}

// The real sample: the skeleton's 1-voxel bones touch along edges and at corners
// everywhere. Regular mode's voxel reading gives the mesh the mask's (26, 6) topology,
// chi = 2 chi(object) = -726, closed and manifold; without the split of doubled faces it
// is non-manifold. Wenger's MDMC is closed and manifold too but reads the contacts as
// separations (chi 354), and needs its fix as much.
TEST(OctreeMethodsRealSample, FrogSkeletonRegularHasTheSkeletonsTopologyAndNeedsTheFix) {
  const volume::Volume mask = frogSkeletonMask();
  const std::int64_t solid = volume::eulerCharacteristic(mask);
  const volume::Volume sdf = toContourable(mask, {});
  for (const auto topology : {cell::RegularTopology::Voxels, cell::RegularTopology::Mdmc}) {
    const bool voxels = topology == cell::RegularTopology::Voxels;
    SCOPED_TRACE(voxels ? "voxels" : "mdmc");
    const mesh::Mesh mesh = contourRegular(sdf, topology);
    const mesh::MeshReport fixed = mesh::validateMesh(mesh, {.selfIntersections = false});
    EXPECT_TRUE(fixed.closed);
    EXPECT_TRUE(fixed.manifold);
    EXPECT_EQ(fixed.inconsistentlyOrientedEdges, 0);
    if (voxels) {
      EXPECT_EQ(fixed.eulerCharacteristic, 2 * solid);
    } else {
      EXPECT_NE(fixed.eulerCharacteristic, 2 * solid);
    }
    EXPECT_LT(meanDistanceToZeroLevel(mesh, sdf), 0.2);
    const mesh::MeshReport unfixed =
        mesh::validateMesh(contourRegular(sdf, topology, /*manifoldFix=*/false), {.selfIntersections = false});
    EXPECT_GT(unfixed.nonManifoldEdges + unfixed.nonManifoldVertices, 0)
        << "the frog skeleton has doubled cells on both sides of ambiguous faces: without the fix it is non-manifold";
  }
}

// The skeleton end to end as `extract` runs it, in both modes: meta-cells of every size
// (seams through tubes and split faces) and the caps where the bones leave the data.
// Regular mode's 67 self-intersecting pairs all had a triangle of a polygon fanned from a
// corner; adaptive mode read the skeleton as MDMC does (chi 354 where the bones' is -726/2).
TEST(OctreeMethodsRealSample, FrogSkeletonHasEveryGuaranteeInBothModesAtEveryMetaCellSize) {
  const volume::Volume mask = frogSkeletonMask();
  const std::int64_t solid = volume::eulerCharacteristic(mask);
  std::size_t regularTriangles = 0;
  for (const ContourMethod method : {ContourMethod::Regular, ContourMethod::Adaptive})
    for (const int metaCellSize : {0, 16, 128}) {
      SCOPED_TRACE(std::string(contourMethodName(method)) + ", meta-cell " + std::to_string(metaCellSize));
      ExtractOptions options;
      options.contour.method = method;
      options.metaCellSize = metaCellSize;
      const mesh::Mesh mesh = extractMesh(mask, options);
      const mesh::MeshReport report = mesh::validateMesh(mesh);
      EXPECT_TRUE(report.closed);
      EXPECT_TRUE(report.manifold);
      EXPECT_EQ(report.eulerCharacteristic, 2 * solid);
      EXPECT_EQ(report.selfIntersectingPairs, 0);
      if (method == ContourMethod::Adaptive) {
        EXPECT_LT(mesh.triangles.size(), regularTriangles * 19 / 20);  // 0.89x at the default bound
        continue;
      }
      if (regularTriangles == 0) regularTriangles = mesh.triangles.size();
      EXPECT_EQ(mesh.triangles.size(), regularTriangles);  // seams change no polygon
    }
}

TEST(OctreeMethodsRealSample, FrogSkeletonAdaptiveIsClosedManifoldWithRegularsTopology) {
  // The skeleton is full of 1-voxel ambiguous faces, doubled faces and 1-voxel cavities
  // inside coarse cells: adaptive mode must come out as closed, manifold and of the same
  // topology as regular mode's MDMC reading, and free of self-intersections.
  const volume::Volume sdf = toContourable(frogSkeletonMask(), {});
  const mesh::MeshReport regular =
      mesh::validateMesh(contourRegular(sdf, cell::RegularTopology::Mdmc), {.selfIntersections = false});
  const mesh::MeshReport adaptive = mesh::validateMesh(contour(sdf, ContourMethod::Adaptive));
  EXPECT_TRUE(adaptive.closed);
  EXPECT_EQ(adaptive.nonManifoldEdges, 0);
  EXPECT_EQ(adaptive.selfIntersectingPairs, 0);
  EXPECT_EQ(adaptive.components, regular.components);
  EXPECT_EQ(adaptive.eulerCharacteristic, regular.eulerCharacteristic);
  EXPECT_LT(adaptive.triangles, regular.triangles);
}

}  // namespace
}  // namespace isovdb::pipeline

namespace isovdb::pipeline {
namespace {

/// Regular mode's topology, exactly: the (6, 18) reading of the voxels, plus one
/// change of the surface's chi by 2 for each pair of cells Wenger's fix regroups.
/// Random voxels are full of ambiguous faces and body-diagonal contacts.
TEST(OctreeMethodsTopology, RegularMeshIsTheSixEighteenReadingPlusTheFixedPairs) {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 random(seed);
    std::bernoulli_distribution inside(0.35);
    auto stream = test::VectorSliceStream::fromFunction({24, 24, 24}, [&](int x, int y, int z) {
      const bool border = x == 0 || y == 0 || z == 0 || x == 23 || y == 23 || z == 23;
      return !border && inside(random) ? 1.f : 0.f;
    });
    auto again = stream.rewound();
    const std::int64_t solid = volume::eulerCharacteristic(again, {}, nullptr, volume::Adjacency::Foreground6);
    Statistics stats;
    const volume::Volume sdf = toContourable(volume::ingestMask(stream, {}), {});
    const mesh::Mesh mesh = contourWithOctree(
        sdf, {.method = ContourMethod::Regular, .topology = cell::RegularTopology::Mdmc}, {}, 128, nullptr, &stats);
    const mesh::MeshReport report = mesh::validateMesh(mesh, {.selfIntersections = false});
    const std::int64_t fixedPairs = stats["meta_cells"]["manifold_fixes"].get<std::int64_t>() / 2;
    EXPECT_TRUE(report.closed) << seed;
    EXPECT_TRUE(report.manifold) << seed;
    EXPECT_GT(fixedPairs, 0) << seed;
    EXPECT_EQ(report.eulerCharacteristic, 2 * (solid + fixedPairs)) << seed;
  }
}

/// Regular mode's default reading is the voxel object's: 26-connected inside, 6-connected
/// outside, whatever the meta-cell size (seams cut through split faces and tubes), free of
/// self-intersections, and both the split faces and the tubes are needed for it. Random voxels at several densities are
/// full of bridges (face-diagonal contacts with the outside going round) and vertex contacts.
TEST(OctreeMethodsTopology, RegularMeshHasTheVoxelObjectsTopology) {
  for (unsigned seed : {1u, 2u, 3u, 6u}) {
    std::mt19937 random(seed);
    std::bernoulli_distribution inside(seed == 6u ? 0.55 : 0.3 + 0.05 * seed);
    auto stream = test::VectorSliceStream::fromFunction({24, 24, 24}, [&](int x, int y, int z) {
      const bool border = x == 0 || y == 0 || z == 0 || x == 23 || y == 23 || z == 23;
      return !border && inside(random) ? 1.f : 0.f;
    });
    auto again = stream.rewound();
    const std::int64_t solid = volume::eulerCharacteristic(again, {});
    const volume::Volume sdf = toContourable(volume::ingestMask(stream, {}), {});
    for (const int metaCellSize : {0, 16}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", meta-cell " + std::to_string(metaCellSize));
      Statistics stats;
      const mesh::Mesh mesh =
          contourWithOctree(sdf, {.method = ContourMethod::Regular}, {}, metaCellSize, nullptr, &stats);
      const mesh::MeshReport report = mesh::validateMesh(mesh);
      const auto& figures = stats[metaCellSize == 0 ? "octree" : "meta_cells"];
      EXPECT_TRUE(report.closed);
      EXPECT_EQ(report.nonManifoldEdges, 0);
      EXPECT_EQ(report.nonManifoldVertices, 0);
      EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
      EXPECT_EQ(report.eulerCharacteristic, 2 * solid);
      EXPECT_EQ(report.selfIntersectingPairs, 0);                   // inside the box: no cap is flattened
      EXPECT_GT(figures["manifold_fixes"].get<std::int64_t>(), 0);  // split faces
      EXPECT_GT(figures["tube_cells"].get<std::int64_t>(), 0);
      std::printf(
          "[voxels seed %u, meta-cell %d] solid chi %lld, mesh chi %lld, %lld triangles, split faces %lld, tubes "
          "%lld\n",
          seed, metaCellSize, static_cast<long long>(solid), static_cast<long long>(report.eulerCharacteristic),
          static_cast<long long>(report.triangles),
          static_cast<long long>(figures["manifold_fixes"].get<std::int64_t>()),
          static_cast<long long>(figures["tube_cells"].get<std::int64_t>()));
    }
    // Without the split the bridges' two cells share four polygons: non-manifold edges.
    const mesh::MeshReport unsplit = mesh::validateMesh(
        contourWithOctree(sdf, {.method = ContourMethod::Regular, .manifoldFix = false}), {.selfIntersections = false});
    EXPECT_GT(unsplit.nonManifoldEdges, 0) << seed;
  }
}

/// The voxel reading keeps every polygon inside its edge's envelope: those of more than
/// four corners (a tube cell's two sectors, a split face's vertex) are fanned from the
/// edge's crossing, so each triangle stays in the one or two cells of its corners, and a
/// quad whose diagonal leaves Ju–Udeshi's envelope takes the other diagonal or the same
/// fan. Without that (--no-intersection-free: corner fans, the better diagonal) these
/// chains of voxels touching at corners (tubes) and at edges (split faces), pairs touching
/// along an edge and a plate with diagonal holes have 15 self-intersecting pairs.
TEST(OctreeMethodsTopology, RegularVoxelReadingContactsAreFreeOfSelfIntersections) {
  std::vector<std::array<int, 3>> voxels;
  for (int i = 2; i < 10; ++i) {
    voxels.push_back({i, i, i});           // a body-diagonal chain
    voxels.push_back({i, 11 - i, i});      // and another, crossing it
    voxels.push_back({14 + i % 2, i, 3});  // face-diagonal staircases
    voxels.push_back({14, i, 6 + i % 2});
  }
  for (int i = 3; i < 20; i += 3) {
    voxels.push_back({i, 18, 18});  // edge-touching pairs
    voxels.push_back({i + 1, 19, 18});
  }
  auto stream = test::VectorSliceStream::fromFunction({24, 24, 24}, [&](int x, int y, int z) {
    const bool plate = x >= 4 && x < 20 && y >= 4 && y < 20 && z == 20;
    const bool hole = x == y && x >= 5 && x < 20;  // diagonal holes through the plate
    const bool listed = std::find(voxels.begin(), voxels.end(), std::array<int, 3>{x, y, z}) != voxels.end();
    return listed || (plate && !hole) ? 1.f : 0.f;
  });
  auto again = stream.rewound();
  const std::int64_t solid = volume::eulerCharacteristic(again, {});
  const volume::Volume sdf = toContourable(volume::ingestMask(stream, {}), {});
  for (const int metaCellSize : {0, 16}) {
    SCOPED_TRACE("meta-cell " + std::to_string(metaCellSize));
    Statistics stats;
    const mesh::Mesh mesh =
        contourWithOctree(sdf, {.method = ContourMethod::Regular}, {}, metaCellSize, nullptr, &stats);
    const mesh::MeshReport report = mesh::validateMesh(mesh);
    EXPECT_GT(stats[metaCellSize == 0 ? "octree" : "meta_cells"]["tube_cells"].get<std::int64_t>(), 0);
    EXPECT_TRUE(report.closed);
    EXPECT_TRUE(report.manifold);
    EXPECT_EQ(report.eulerCharacteristic, 2 * solid);
    EXPECT_EQ(report.selfIntersectingPairs, 0);
    const mesh::Mesh plain =
        contourWithOctree(sdf, {.method = ContourMethod::Regular, .intersectionFree = false}, {}, metaCellSize);
    EXPECT_GT(mesh::validateMesh(plain).selfIntersectingPairs, 0);
    EXPECT_LT(plain.triangles.size(), mesh.triangles.size());  // the fans' extra triangles
  }
}

/// Adaptive mode has regular mode's topology on the same voxels: one vertex per DMC
/// group at the finest level with the same fix, and coarse leaves only where one
/// vertex stands for a disk.
TEST(OctreeMethodsTopology, AdaptiveMeshHasRegularsTopologyOnRandomVoxels) {
  for (unsigned seed : {4u, 5u}) {
    std::mt19937 random(seed);
    std::bernoulli_distribution inside(0.35);
    auto stream = test::VectorSliceStream::fromFunction({24, 24, 24}, [&](int x, int y, int z) {
      const bool border = x == 0 || y == 0 || z == 0 || x == 23 || y == 23 || z == 23;
      return !border && inside(random) ? 1.f : 0.f;
    });
    const volume::Volume sdf = toContourable(volume::ingestMask(stream, {}), {});
    const mesh::MeshReport regular = mesh::validateMesh(
        contourWithOctree(sdf, {.method = ContourMethod::Regular, .topology = cell::RegularTopology::Mdmc}),
        {.selfIntersections = false});
    const mesh::MeshReport adaptive =
        mesh::validateMesh(contour(sdf, ContourMethod::Adaptive), {.selfIntersections = false});
    EXPECT_TRUE(adaptive.closed) << seed;
    EXPECT_EQ(adaptive.nonManifoldEdges, 0) << seed;
    EXPECT_EQ(adaptive.components, regular.components) << seed;
    EXPECT_EQ(adaptive.eulerCharacteristic, regular.eulerCharacteristic) << seed;
  }
}

}  // namespace
}  // namespace isovdb::pipeline
