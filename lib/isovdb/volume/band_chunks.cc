// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/band_chunks.h"

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/TopologyToLevelSet.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <mutex>

#include "isovdb/volume/interface_band.h"

namespace isovdb::volume {

namespace {

constexpr int kLeafDim = 8;

/// Copy of the mask restricted to `region` (8-aligned), built by probing leaves
/// and 8^3 tiles, so the cost is that of the region, not of the whole grid.
/// Returns false when the region holds no boundary between inside and outside.
bool extractRegion(const MaskGrid& mask, const openvdb::CoordBBox& region, MaskGrid& out) {
  auto acc = mask.getConstAccessor();
  MaskGrid::TreeType& tree = out.tree();
  bool anyOn = false, anyOff = false;
  for (int z = region.min().z(); z <= region.max().z(); z += kLeafDim)
    for (int y = region.min().y(); y <= region.max().y(); y += kLeafDim)
      for (int x = region.min().x(); x <= region.max().x(); x += kLeafDim) {
        const openvdb::Coord origin(x, y, z);
        if (const auto* leaf = acc.probeConstLeaf(origin)) {
          tree.addLeaf(new MaskGrid::TreeType::LeafNodeType(*leaf));
          anyOn = anyOn || !leaf->isValueMaskOff();
          anyOff = anyOff || !leaf->isValueMaskOn();
        } else if (acc.isValueOn(origin)) {
          tree.addTile(1, origin, true, true);
          anyOn = true;
        } else {
          anyOff = true;
        }
      }
  return anyOn && anyOff;
}

openvdb::Coord alignDown(const openvdb::Coord& c, int step) {
  auto down = [step](int v) { return v >= 0 ? v / step * step : -((-v + step - 1) / step) * step; };
  return {down(c.x()), down(c.y()), down(c.z())};
}

}  // namespace

/// topologyToLevelSet's PDE normalisation is off by up to 1.3 voxels inside the
/// band (sphere test); the sweep brings the error below 0.4 voxel.
FieldGrid::Ptr bandOf(const MaskGrid& mask, const DistanceFieldOptions& options, Interrupter* interrupter) {
  detail::VdbInterrupter vdbInterrupter(interrupter);
  FieldGrid::Ptr sdf = openvdb::tools::topologyToLevelSet(mask, options.halfWidth, options.closingSteps,
                                                          /*dilation=*/0, /*smoothingSteps=*/0, &vdbInterrupter);
  if (options.redistance && sdf->activeVoxelCount() > 0) sdf = openvdb::tools::sdfToSdf(*sdf, 0.f, 1);
  return sdf;
}

namespace {

/// The interface band of the mask, after the morphological closing asked for.
std::size_t interfaceBandInChunks(const MaskGrid& mask, const DistanceFieldOptions& options, const BandLeafSink& sink,
                                  Interrupter* interrupter) {
  constexpr int kDefaultChunk = 64;
  const int chunk = options.chunkSize > 0 ? options.chunkSize : kDefaultChunk;
  if (options.closingSteps == 0) return computeInterfaceBand(mask, options.halfWidth, chunk, sink, interrupter);
  return computeInterfaceBand(*closedMask(mask, options.closingSteps), options.halfWidth, chunk, sink, interrupter);
}

}  // namespace

MaskGrid::Ptr closedMask(const MaskGrid& mask, int steps) {
  MaskGrid::Ptr closed = mask.deepCopy();
  openvdb::tools::dilateActiveValues(closed->tree(), steps, openvdb::tools::NN_FACE, openvdb::tools::PRESERVE_TILES);
  openvdb::tools::erodeActiveValues(closed->tree(), steps, openvdb::tools::NN_FACE, openvdb::tools::PRESERVE_TILES);
  openvdb::tools::pruneInactive(closed->tree());
  return closed;
}

std::size_t computeBandInChunks(const MaskGrid& mask, const DistanceFieldOptions& options, const BandLeafSink& sink,
                                Interrupter* interrupter) {
  if (options.method == DistanceMethod::Interface) return interfaceBandInChunks(mask, options, sink, interrupter);
  ProgressStage progress(interrupter, "distance field");
  openvdb::CoordBBox bbox;
  if (!mask.tree().evalActiveVoxelBoundingBox(bbox)) return 0;
  // Each chunk is computed from the mask around it with a halo wide enough that
  // the halo's cut faces cannot reach the chunk's band: their own band (halfWidth)
  // plus the chunk's (halfWidth) plus closing, plus a voxel of slack, rounded up
  // to whole leaves.
  const int halo = (2 * options.halfWidth + 2 * options.closingSteps + 2 + kLeafDim - 1) / kLeafDim * kLeafDim;
  const int chunk = options.chunkSize;
  const openvdb::Coord first = alignDown(bbox.min().offsetBy(-options.halfWidth - 1), chunk);
  const openvdb::Coord last = bbox.max().offsetBy(options.halfWidth + 1);
  std::vector<openvdb::Coord> chunks;
  for (int z = first.z(); z <= last.z(); z += chunk)
    for (int y = first.y(); y <= last.y(); y += chunk)
      for (int x = first.x(); x <= last.x(); x += chunk) chunks.emplace_back(x, y, z);
  const float outside = static_cast<float>(options.halfWidth);
  const openvdb::tools::SignedFloodFillOp<FieldGrid::TreeType> fillLeaf(outside, -outside);
  // Chunks run in parallel, as many at once as TBB has threads (one with --threads 1,
  // so serial mode holds one chunk's working set); each hands out only the leaves
  // inside its own chunk, so what the sink receives does not depend on the order.
  std::mutex handOut;
  std::size_t done = 0;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, chunks.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
          const openvdb::CoordBBox inner(chunks[c], chunks[c].offsetBy(chunk - 1));
          openvdb::CoordBBox outer = inner;
          outer.expand(halo);
          MaskGrid region(false);
          std::vector<std::unique_ptr<FieldLeaf>> leaves;
          if (extractRegion(mask, outer, region)) {
            FieldGrid::Ptr band = bandOf(region, options, nullptr);
            std::vector<openvdb::Coord> origins;
            for (auto leaf = band->tree().cbeginLeaf(); leaf; ++leaf)
              if (inner.isInside(leaf->origin())) origins.push_back(leaf->origin());
            for (const openvdb::Coord& origin : origins) {
              leaves.emplace_back(band->tree().stealNode<FieldLeaf>(origin, band->background(), false));
              fillLeaf(*leaves.back());
            }
          }
          if (!leaves.empty()) sink(std::move(leaves));
          const std::lock_guard<std::mutex> lock(handOut);
          progress.update(static_cast<double>(++done), static_cast<double>(chunks.size()));
        }
      },
      tbb::simple_partitioner());
  return chunks.size();
}

}  // namespace isovdb::volume
