// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The whole-volume pipeline: meta-cells contoured independently, seams closed by
// edge-octree stitching. Every stitched mesh must keep the guarantees of the
// single-block mesh (closed; regular: manifold; adaptive: no self-intersection)
// and its Euler characteristic, also with features placed exactly on a
// meta-face, a meta-edge and a meta-vertex; output bytes must not depend on the
// thread count.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "generators/shapes.h"
#include "isovdb/io/ply.h"
#include "isovdb/io/ply_stream_writer.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/volume/ingest.h"
#include "support/test_support.h"
#include "support/vector_slice_stream.h"

namespace isovdb::pipeline {
namespace {

volume::Volume sdfOf(io::SliceStream& stream) { return toContourable(volume::ingestMask(stream, {}), {}); }

volume::Volume shapeSdf(samples::ShapeKind kind, int size) {
  auto stream = samples::makeShapeStream(kind, {.size = size});
  return sdfOf(*stream);
}

/// A mask volume of 64^3 voxels from an inside test.
volume::Volume maskSdf(const std::function<bool(int, int, int)>& inside) {
  auto stream = test::VectorSliceStream::fromFunction(
      {64, 64, 64}, [&](int x, int y, int z) { return inside(x, y, z) ? 1.0f : 0.0f; });
  return sdfOf(stream);
}

struct Contoured {
  mesh::Mesh mesh;
  Statistics stats;
};

Contoured contour(const volume::Volume& sdf, ContourMethod method, int metaCellSize) {
  Contoured out;
  out.mesh = contourWithOctree(sdf, {.method = method}, {}, metaCellSize, nullptr, &out.stats);
  return out;
}

/// Checks a stitched mesh against the single-block one; returns its report.
void expectSameGuaranteesAsOneBlock(const volume::Volume& sdf, ContourMethod method, int metaCellSize) {
  const bool regular = method == ContourMethod::Regular;
  const Contoured single = contour(sdf, method, 0);
  const Contoured stitched = contour(sdf, method, metaCellSize);
  const mesh::MeshReport one = mesh::validateMesh(single.mesh);
  const mesh::MeshReport many = mesh::validateMesh(stitched.mesh);
  SCOPED_TRACE((regular ? "regular, meta-cell " : "adaptive, meta-cell ") + std::to_string(metaCellSize));
  ASSERT_GT(many.triangles, 0);
  EXPECT_TRUE(many.closed);
  EXPECT_EQ(many.inconsistentlyOrientedEdges, 0);
  EXPECT_EQ(many.eulerCharacteristic, one.eulerCharacteristic);
  EXPECT_EQ(many.components, one.components);
  EXPECT_EQ(many.selfIntersectingPairs, 0);
  if (regular) {
    EXPECT_EQ(many.nonManifoldEdges, 0);
    EXPECT_EQ(many.nonManifoldVertices, 0);
    // Regular leaves are 1-voxel cells on the same grid either way: the same polygons. Only
    // a quad lying on its envelope's boundary (flat, across a one-voxel sheet) may be fanned
    // (two more triangles) on one side of the vertices' last bits and not on the other.
    EXPECT_NEAR(static_cast<double>(many.triangles), static_cast<double>(one.triangles), 0.01 * one.triangles);
  }
  // The seams were really stitched, and no deferred edge lacked a kept cell.
  const auto& st = stitched.stats.json()["stitch"];
  EXPECT_GT(st["edges"].get<std::int64_t>(), 0);
  EXPECT_EQ(st["missing_cells"].get<std::int64_t>(), 0);
  const auto& mc = stitched.stats.json()["meta_cells"];
  EXPECT_EQ(mc["contoured"].get<std::int64_t>() + mc["skipped_without_sign_change"].get<std::int64_t>(),
            mc["candidates"].get<std::int64_t>());
}

struct StitchCase {
  samples::ShapeKind shape;
  int metaCellSize;
};

class StitchedShapes : public ::testing::TestWithParam<StitchCase> {};

TEST_P(StitchedShapes, RegularAndAdaptiveKeepTheSingleBlockGuarantees) {
  const volume::Volume sdf = shapeSdf(GetParam().shape, 64);
  expectSameGuaranteesAsOneBlock(sdf, ContourMethod::Regular, GetParam().metaCellSize);
  expectSameGuaranteesAsOneBlock(sdf, ContourMethod::Adaptive, GetParam().metaCellSize);
}

std::vector<StitchCase> stitchCases() {
  std::vector<StitchCase> cases;
  for (const auto shape : {samples::ShapeKind::Sphere, samples::ShapeKind::Torus, samples::ShapeKind::Genus2,
                           samples::ShapeKind::GyroidSlab, samples::ShapeKind::SaltDome})
    for (const int size : {16, 32}) cases.push_back({shape, size});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Shapes, StitchedShapes, ::testing::ValuesIn(stitchCases()), [](const auto& info) {
  std::string name(samples::shapeName(info.param.shape));
  std::replace(name.begin(), name.end(), '-', '_');
  return name + "_" + std::to_string(info.param.metaCellSize);
});

// Features placed exactly on the partition of 32-voxel meta-cells: the samples of
// the feature lie on a meta-face (x = 32), a meta-edge (y = z = 32) or at a
// meta-vertex (32, 32, 32), where a naive stitcher loses or doubles polygons.

TEST(StitchedFeatures, ThinSheetOnAMetaFace) {
  // A one-voxel sheet in the plane x = 32, with a hole whose rim crosses meta-edges.
  const volume::Volume sdf = maskSdf([](int x, int y, int z) {
    const bool hole = (y - 32) * (y - 32) + (z - 32) * (z - 32) < 36;
    return x == 32 && y >= 8 && y < 56 && z >= 8 && z < 56 && !hole;
  });
  for (const auto method : {ContourMethod::Regular, ContourMethod::Adaptive})
    expectSameGuaranteesAsOneBlock(sdf, method, 32);
}

TEST(StitchedFeatures, TunnelAlongAMetaEdge) {
  // A box pierced along x by a one-voxel tunnel on the line y = z = 32, plus a
  // one-voxel rod along the meta-edge y = 32, z = 16 beside it.
  const volume::Volume sdf = maskSdf([](int x, int y, int z) {
    const bool box = x >= 10 && x < 54 && y >= 24 && y < 41 && z >= 24 && z < 41;
    const bool tunnel = y == 32 && z == 32;
    const bool rod = x >= 10 && x < 54 && y == 32 && z == 16;
    return (box && !tunnel) || rod;
  });
  for (const auto method : {ContourMethod::Regular, ContourMethod::Adaptive}) {
    expectSameGuaranteesAsOneBlock(sdf, method, 32);
    expectSameGuaranteesAsOneBlock(sdf, method, 16);
  }
}

TEST(StitchedFeatures, SharpCornerAtAMetaVertex) {
  // A box whose corner voxel sits at the meta-vertex (32, 32, 32), where eight meta-cells meet.
  const volume::Volume sdf =
      maskSdf([](int x, int y, int z) { return x >= 16 && x <= 32 && y >= 16 && y <= 32 && z >= 16 && z <= 32; });
  for (const auto method : {ContourMethod::Regular, ContourMethod::Adaptive}) {
    expectSameGuaranteesAsOneBlock(sdf, method, 32);
    expectSameGuaranteesAsOneBlock(sdf, method, 16);
  }
}

TEST(StitchedFeatures, PinchedBoxesAtAMetaVertexStayManifoldInRegularMode) {
  // Two boxes that touch only along an edge through the meta-vertex: ambiguous
  // faces on the seams, which Wenger's fix must resolve across meta-cells.
  const volume::Volume sdf = maskSdf([](int x, int y, int z) {
    const bool low = x >= 16 && x <= 32 && y >= 16 && y <= 32 && z >= 16 && z <= 32;
    const bool high = x > 32 && x < 48 && y > 32 && y < 48 && z >= 16 && z <= 32;
    return low || high;
  });
  expectSameGuaranteesAsOneBlock(sdf, ContourMethod::Regular, 32);
  expectSameGuaranteesAsOneBlock(sdf, ContourMethod::Regular, 16);
}

TEST(StitchedOutput, SameBytesForOneTwoAndEightThreads) {
  const volume::Volume sdf = shapeSdf(samples::ShapeKind::SaltDome, 64);
  test::TempDir dir;
  for (const auto method : {ContourMethod::Regular, ContourMethod::Adaptive}) {
    std::string reference;
    for (const int threads : {1, 2, 8}) {
      ExtractOptions options;
      options.contour.method = method;
      options.metaCellSize = 16;
      options.threads = threads;
      const auto path = dir.path() / ("t" + std::to_string(threads) + ".ply");
      io::PlyStreamWriter writer(path);
      extractInto(sdf, options, writer);
      writer.commit();
      const std::string bytes = test::readFile(path);
      if (reference.empty()) reference = bytes;
      EXPECT_EQ(bytes, reference) << threads << " threads, method " << contourMethodName(method);
    }
    // And the streamed file is the collected mesh.
    ExtractOptions collect;
    collect.contour.method = method;
    collect.metaCellSize = 16;
    const mesh::Mesh collected = extractMesh(sdf, collect);
    const mesh::Mesh streamed = io::readPly(dir.path() / "t1.ply");
    EXPECT_EQ(streamed.positions, collected.positions);
    EXPECT_EQ(streamed.triangles, collected.triangles);
  }
}

TEST(StitchedOutput, AMaskContouredLayerByLayerIsTheWholeFieldsMesh) {
  // extract() computes a mask's distance field one layer of meta-cells at a time
  // (volume/slab_band.h); the mesh must be the one of the whole field, for every
  // thread count.
  for (const auto kind : {samples::ShapeKind::SaltDome, samples::ShapeKind::GyroidSlab}) {
    auto stream = samples::makeShapeStream(kind, {.size = 64});
    const volume::Volume mask = volume::ingestMask(*stream, {});
    const volume::Volume sdf = toContourable(mask, {});
    for (const auto method : {ContourMethod::Regular, ContourMethod::Adaptive})
      for (const int threads : {1, 2}) {
        ExtractOptions options;
        options.contour.method = method;
        options.regularTopology = cell::RegularTopology::Voxels;  // the mask's reading for its field too
        options.metaCellSize = 16;
        options.threads = threads;
        Statistics stats;
        const mesh::Mesh layered = extractMesh(mask, options, nullptr, &stats);
        const mesh::Mesh whole = extractMesh(sdf, options);
        ASSERT_GT(whole.triangles.size(), 0u);
        EXPECT_EQ(layered.positions, whole.positions) << contourMethodName(method) << ", " << threads << " threads";
        EXPECT_EQ(layered.triangles, whole.triangles) << contourMethodName(method) << ", " << threads << " threads";
        EXPECT_TRUE(stats.json()["distance_field"]["computed_by_meta_cell_layer"].get<bool>());
      }
  }
}

TEST(StitchedOutput, RejectsAMetaCellSizeOutsideTheRange) {
  const volume::Volume sdf = shapeSdf(samples::ShapeKind::Sphere, 32);
  for (const int size : {8, 24, 1024}) {
    EXPECT_THROW(contourWithOctree(sdf, {.method = ContourMethod::Regular}, {}, size), InputError) << size;
  }
}

}  // namespace
}  // namespace isovdb::pipeline
