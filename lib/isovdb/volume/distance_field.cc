#include "isovdb/volume/distance_field.h"

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/TopologyToLevelSet.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <mutex>
#include <vector>

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

namespace {

constexpr int kLeafDim = 8;

/// Narrow band of one grid with OpenVDB's tools: topologyToLevelSet, then
/// (optionally) one fast-sweeping pass. topologyToLevelSet's PDE normalisation
/// is off by up to 1.3 voxels inside the band (sphere test); the sweep brings the
/// error below 0.4 voxel.
FieldGrid::Ptr bandOf(const MaskGrid& mask, const DistanceFieldOptions& options, Interrupter* interrupter) {
  detail::VdbInterrupter vdbInterrupter(interrupter);
  FieldGrid::Ptr sdf = openvdb::tools::topologyToLevelSet(mask, options.halfWidth, options.closingSteps,
                                                          /*dilation=*/0, /*smoothingSteps=*/0, &vdbInterrupter);
  if (options.redistance && sdf->activeVoxelCount() > 0) sdf = openvdb::tools::sdfToSdf(*sdf, 0.f, 1);
  return sdf;
}

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

Volume distanceField(const Volume& mask, const DistanceFieldOptions& options, Interrupter* interrupter) {
  const MaskGrid& grid = maskGrid(mask);
  if (options.halfWidth < 1 || options.halfWidth > 64)
    throw InputError("distance field: half-width " + std::to_string(options.halfWidth) +
                     " is out of range, expected 1..64 voxels");
  if (options.closingSteps < 0) throw InputError("distance field: closing steps must be >= 0");
  if (options.chunkSize < 0 || options.chunkSize % kLeafDim != 0)
    throw InputError("distance field: chunk size " + std::to_string(options.chunkSize) +
                     " must be 0 or a positive multiple of 8 voxels");
  ProgressStage progress(interrupter, "distance field");

  FieldGrid::Ptr sdf;
  openvdb::CoordBBox bbox;
  if (options.chunkSize == 0 || !grid.tree().evalActiveVoxelBoundingBox(bbox)) {
    sdf = bandOf(grid, options, interrupter);
  } else {
    // Chunks of chunkSize^3 voxels, each computed from the mask around it with a
    // halo wide enough that the halo's cut faces cannot reach the chunk's band:
    // their own band (halfWidth) plus the chunk's (halfWidth) plus closing, plus a
    // voxel of slack, rounded up to whole leaves.
    const int halo = (2 * options.halfWidth + 2 * options.closingSteps + 2 + kLeafDim - 1) / kLeafDim * kLeafDim;
    const int chunk = options.chunkSize;
    sdf = FieldGrid::create(static_cast<float>(options.halfWidth));
    const openvdb::Coord first = alignDown(bbox.min().offsetBy(-options.halfWidth - 1), chunk);
    const openvdb::Coord last = bbox.max().offsetBy(options.halfWidth + 1);
    std::vector<openvdb::Coord> chunks;
    for (int z = first.z(); z <= last.z(); z += chunk)
      for (int y = first.y(); y <= last.y(); y += chunk)
        for (int x = first.x(); x <= last.x(); x += chunk) chunks.emplace_back(x, y, z);
    // Chunks run in parallel, as many at once as TBB has threads (one with --threads 1,
    // so serial mode holds one chunk's working set); each adds only the leaves inside
    // its own chunk, so the result does not depend on the order.
    std::mutex merge;
    std::size_t done = 0;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t c = r.begin(); c != r.end(); ++c) {
        const openvdb::CoordBBox inner(chunks[c], chunks[c].offsetBy(chunk - 1));
        openvdb::CoordBBox outer = inner;
        outer.expand(halo);
        MaskGrid region(false);
        std::vector<FieldGrid::TreeType::LeafNodeType*> leaves;
        if (extractRegion(grid, outer, region)) {
          FieldGrid::Ptr band = bandOf(region, options, nullptr);
          std::vector<openvdb::Coord> origins;
          for (auto leaf = band->tree().cbeginLeaf(); leaf; ++leaf)
            if (inner.isInside(leaf->origin())) origins.push_back(leaf->origin());
          for (const openvdb::Coord& origin : origins)
            leaves.push_back(band->tree().stealNode<FieldGrid::TreeType::LeafNodeType>(origin, band->background(), false));
        }
        const std::lock_guard<std::mutex> lock(merge);
        for (auto* leaf : leaves) sdf->tree().addLeaf(leaf);
        progress.update(static_cast<double>(++done), static_cast<double>(chunks.size()));
      }
    }, tbb::simple_partitioner());
    // Inactive space between chunks' bands: negative inside, positive outside.
    openvdb::tools::signedFloodFill(sdf->tree());
    openvdb::tools::pruneLevelSet(sdf->tree());
  }
  progress.update(1, 1);
  sdf->setTransform(openvdb::math::Transform::createLinearTransform(1.0));
  sdf->setName("sdf");
  sdf->setGridClass(openvdb::GRID_LEVEL_SET);
  return Volume(VolumeKind::DistanceField, sdf, mask.geometry(), mask.name());
}

Volume interiorMask(const Volume& sdf, double iso) {
  if (sdf.kind() != VolumeKind::DistanceField)
    throw InputError("'" + sdf.name() + "': interior mask needs a distance field");
  MaskGrid::Ptr mask = openvdb::tools::sdfInteriorMask(fieldGrid(sdf), static_cast<float>(iso));
  return Volume(VolumeKind::Mask, mask, sdf.geometry(), sdf.name());
}

}  // namespace isovdb::volume
