// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// A distributed run's parts (isovdb.distributed) without Dask: slabs read through a
// SliceWindow, contoured into MetaCellPieces, the bytes decoded and assembled by the
// client's extractInto: the same mesh, value for value, as one process.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <optional>
#include <string>
#include <vector>

#include "generators/shapes.h"
#include "isovdb/errors.h"
#include "isovdb/io/slice_window.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/meta_cell_pieces.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::pipeline {
namespace {

volume::Volume shapeMask(samples::ShapeKind kind, int size, const std::optional<io::SliceWindow>& window = {}) {
  auto stream = samples::makeShapeStream(kind, {.size = size});
  if (!window) return volume::ingestMask(*stream, {});
  io::SliceWindowStream windowed(*stream, *window);
  return volume::ingestMask(windowed, {});
}

TEST(SliceWindow, KeepsExactlyTheWindowsVoxelsAndTheWholeBox) {
  const volume::Volume whole = shapeMask(samples::ShapeKind::SaltDome, 64);
  const io::SliceWindow window{16, 40};
  const volume::Volume slab = shapeMask(samples::ShapeKind::SaltDome, 64, window);
  std::int64_t inWindow = 0;
  const auto& wholeTree = volume::maskGrid(whole).tree();
  const auto& slabTree = volume::maskGrid(slab).tree();
  for (auto v = wholeTree.cbeginValueOn(); v; ++v) {
    openvdb::CoordBBox box;
    v.getBoundingBox(box);
    for (auto c = box.begin(); c; ++c) {
      const bool inside = (*c).z() >= window.begin && (*c).z() < window.end;
      inWindow += inside ? 1 : 0;
      EXPECT_EQ(slabTree.isValueOn(*c), inside) << *c;
    }
  }
  EXPECT_GT(inWindow, 0);
  EXPECT_EQ(static_cast<std::int64_t>(slabTree.activeVoxelCount()), inWindow);
  const auto wholeBox = volume::sampledBox(whole), slabBox = volume::sampledBox(slab);
  ASSERT_TRUE(wholeBox && slabBox);
  EXPECT_EQ(wholeBox->min, slabBox->min);
  EXPECT_EQ(wholeBox->max, slabBox->max);
}

/// One process's mesh, and the mesh a client assembles from slabs of `layersPerSlab`
/// meta-cell layers, each contoured from its own window of the file.
struct TwoRuns {
  mesh::Mesh single, assembled;
  std::int64_t slabs = 0, pieces = 0;
};

/// `halo`: voxels each slab reads beyond its layers (unset: slabHalo's).
TwoRuns runBothWays(samples::ShapeKind kind, int size, const ExtractOptions& options, int layersPerSlab,
                    std::optional<int> halo = std::nullopt) {
  TwoRuns result;
  mesh::MeshCollector single;
  extractInto(shapeMask(kind, size), options, single);
  result.single = std::move(single.mesh);

  const int s = options.metaCellSize, reach = halo.value_or(slabHalo(options));
  std::vector<std::string> slabBytes;
  for (int k = -1; k * s <= size; k += layersPerSlab) {
    MetaCellPieces pieces;
    ExtractPart task;
    task.layers = MetaCellLayers{k, k + layersPerSlab};
    task.pieces = &pieces;
    mesh::MeshCollector nothing;
    extractInto(shapeMask(kind, size, io::SliceWindow{k * s - reach, (k + layersPerSlab) * s + reach}), options,
                nothing, nullptr, nullptr, &task);
    EXPECT_EQ(nothing.mesh.triangles.size(), 0U);  // a task's meshes all go to its pieces
    result.pieces += pieces.count();
    slabBytes.push_back(pieces.release());
  }
  result.slabs = static_cast<std::int64_t>(slabBytes.size());

  std::size_t next = 0;
  std::optional<MetaCellPieceReader> reader;
  ExtractPart client;
  client.received = [&](volume::MetaCellIndex& index, contour::MetaCellMesh& block) {
    for (;;) {
      if (reader && reader->next(index, block)) return true;
      if (next == slabBytes.size()) return false;
      reader.emplace(slabBytes[next], "slab " + std::to_string(next));
      ++next;
    }
  };
  mesh::MeshCollector assembled;
  extractInto(shapeMask(kind, size, io::SliceWindow{0, 0}), options, assembled, nullptr, nullptr, &client);
  result.assembled = std::move(assembled.mesh);
  return result;
}

class ExtractParts : public ::testing::TestWithParam<ContourMethod> {};

TEST_P(ExtractParts, SlabsAssembleIntoOneProcesssMesh) {
  ExtractOptions options;
  options.contour.method = GetParam();
  options.metaCellSize = 16;
  for (const int layersPerSlab : {1, 3}) {
    const TwoRuns runs = runBothWays(samples::ShapeKind::SaltDome, 72, options, layersPerSlab);
    EXPECT_GE(runs.slabs, layersPerSlab == 1 ? 5 : 2);
    EXPECT_GT(runs.pieces, runs.slabs);
    ASSERT_GT(runs.single.triangles.size(), 1000U);
    EXPECT_EQ(runs.assembled.positions, runs.single.positions) << layersPerSlab;
    EXPECT_EQ(runs.assembled.triangles, runs.single.triangles) << layersPerSlab;
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, ExtractParts, ::testing::Values(ContourMethod::Adaptive, ContourMethod::Regular));

TEST(ExtractParts, SlabsWithoutTheirHaloDoNotAssembleIntoTheSameMesh) {
  // The halo is what makes a slab's samples the whole volume's: without it the band
  // differs near the slab's faces (this shows the comparison above can fail).
  ExtractOptions options;
  options.metaCellSize = 16;
  const TwoRuns runs = runBothWays(samples::ShapeKind::SaltDome, 72, options, 1, /*halo=*/0);
  EXPECT_NE(runs.assembled.positions, runs.single.positions);
}

TEST(SeamStitcher, HoldsAboutTwoLayersOfKeptCells) {
  // Each layer's seams are stitched once the next layer is in, and their cells dropped:
  // a ball's surface is spread evenly over z (2 pi R dz), 10 layers of meta-cells here,
  // and the stitcher holds about two or three of them at a time.
  ExtractOptions options;
  options.contour.method = ContourMethod::Regular;
  options.metaCellSize = 16;
  Statistics stats;
  mesh::MeshCollector mesh;
  extractInto(shapeMask(samples::ShapeKind::Sphere, 200), options, mesh, nullptr, &stats);
  const auto& stitch = stats.json()["stitch"];
  const auto held = stitch["peak_held_seam_cells"].get<std::int64_t>();
  const auto all = stitch["seam_cells"].get<std::int64_t>();
  EXPECT_GT(held, 0);
  EXPECT_LT(3 * held, all) << held << " of " << all;
  EXPECT_EQ(stitch["missing_cells"].get<std::int64_t>(), 0);
}

TEST(MetaCellPieces, TruncatedOrForeignBytesAreRefusedByName) {
  ExtractOptions options;
  options.metaCellSize = 16;
  MetaCellPieces pieces;
  ExtractPart task;
  task.layers = MetaCellLayers{1, 3};
  task.pieces = &pieces;
  mesh::MeshCollector nothing;
  extractInto(shapeMask(samples::ShapeKind::Sphere, 48), options, nothing, nullptr, nullptr, &task);
  ASSERT_GT(pieces.count(), 1);
  EXPECT_GT(pieces.seamBytes(), 0);
  const std::string bytes = pieces.bytes();
  volume::MetaCellIndex index{};
  contour::MetaCellMesh block;
  std::int64_t read = 0;
  MetaCellPieceReader whole(bytes, "slab 1");
  while (whole.next(index, block)) ++read;
  EXPECT_EQ(read, pieces.count());

  MetaCellPieceReader cut(std::string_view(bytes).substr(0, bytes.size() - 5), "slab 1");
  try {
    while (cut.next(index, block)) {
    }
    FAIL() << "truncated pieces were read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slab 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MetaCellPieceReader("not pieces at all", "slab 2"), InputError);
}

TEST(ExtractParts, OnlyMasksInMetaCellsTakePart) {
  ExtractOptions options;
  options.contour.method = ContourMethod::Vdb;
  MetaCellPieces pieces;
  ExtractPart task;
  task.layers = MetaCellLayers{0, 1};
  task.pieces = &pieces;
  mesh::MeshCollector nothing;
  EXPECT_THROW(extractInto(shapeMask(samples::ShapeKind::Sphere, 32), options, nothing, nullptr, nullptr, &task),
               InputError);
}

}  // namespace
}  // namespace isovdb::pipeline
