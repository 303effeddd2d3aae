// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/slab_band.h"

#include <algorithm>
#include <limits>
#include <mutex>

#include "isovdb/volume/band_chunks.h"

namespace isovdb::volume {

namespace {

constexpr int kLeafDim = 8;

int floorDiv(int v, int step) { return v >= 0 ? v / step : -((-v + step - 1) / step); }

}  // namespace

SlabBand::SlabBand(const Volume& mask, const DistanceFieldOptions& options, int metaCellSize, int apron)
    : mask_(maskGrid(mask)),
      halfWidth_(options.halfWidth),
      size_(metaCellSize),
      apron_(apron),
      // A layer reads leaves down to A + 7 voxels below it (its apron) and the
      // partition looks at leaves whose box grown by two voxels touches it: 16 covers both.
      margin_(std::max(apron, 1) + 2 * kLeafDim),
      band_(FieldGrid::create(static_cast<float>(options.halfWidth))) {
  checkDistanceFieldOptions(options);
  constexpr int kDefaultChunk = 64;
  const int chunk = options.chunkSize > 0 ? options.chunkSize : kDefaultChunk;
  if (options.closingSteps > 0) closed_ = closedMask(mask_, options.closingSteps);
  chunks_ = std::make_unique<InterfaceBandChunks>(closed_ ? *closed_ : mask_, halfWidth_, chunk);
  band_->setTransform(openvdb::math::Transform::createLinearTransform(1.0));
  band_->setGridClass(openvdb::GRID_LEVEL_SET);
  held_ = Volume(VolumeKind::DistanceField, band_, mask.geometry(), mask.name());
  figures_.minValue = std::numeric_limits<float>::max();
  figures_.maxValue = std::numeric_limits<float>::lowest();
  if (const auto range = chunks_->zRange()) {
    firstLayer_ = floorDiv(range->first - margin_, size_);
    endLayer_ = floorDiv(range->second - 1 + margin_, size_) + 1;
    computedEnd_ = range->first;
  }
}

std::vector<MetaCellIndex> SlabBand::advanceTo(int k, float iso, const std::function<void()>& chunkDone) {
  dropBelow(k * size_ - margin_);
  // Chunks start at multiples of the chunk size: compute every one that starts below the layer's reach.
  const int chunk = chunks_->chunkSize();
  const int reachEnd = (floorDiv(k * size_ + size_ + margin_, chunk) + 1) * chunk;
  if (reachEnd > computedEnd_) {
    std::mutex adding;
    chunks_->compute(
        computedEnd_, reachEnd,
        [&](std::vector<std::unique_ptr<FieldLeaf>>&& leaves) {
          // The chunk's figures first, outside the lock (chunks arrive from every thread).
          Figures chunk;
          chunk.minValue = std::numeric_limits<float>::max();
          chunk.maxValue = std::numeric_limits<float>::lowest();
          openvdb::CoordBBox box;
          std::int64_t bytes = 0;
          for (const auto& leaf : leaves) {
            bytes += static_cast<std::int64_t>(leaf->memUsage());
            if (leaf->isEmpty()) continue;
            chunk.activeVoxels += static_cast<std::int64_t>(leaf->onVoxelCount());
            ++chunk.leafCount;
            for (auto v = leaf->cbeginValueOn(); v; ++v) {
              chunk.minValue = std::min(chunk.minValue, *v);
              chunk.maxValue = std::max(chunk.maxValue, *v);
            }
            leaf->evalActiveBoundingBox(box);
          }
          const std::lock_guard<std::mutex> lock(adding);
          for (auto& leaf : leaves) band_->tree().addLeaf(leaf.release());
          figures_.activeVoxels += chunk.activeVoxels;
          figures_.leafCount += chunk.leafCount;
          figures_.minValue = std::min(figures_.minValue, chunk.minValue);
          figures_.maxValue = std::max(figures_.maxValue, chunk.maxValue);
          activeBox_.expand(box);
          heldBytes_ += bytes;
          figures_.peakBytes = std::max(figures_.peakBytes, heldBytes_);
        },
        chunkDone);
    computedEnd_ = reachEnd;
  }
  const MetaCellPartition partition = partitionMetaCells(held_, size_, iso);
  std::vector<MetaCellIndex> layer;
  for (const MetaCellIndex& index : partition.cells)
    if (index[2] == k) layer.push_back(index);
  return layer;
}

void SlabBand::read(const MetaCellIndex& index, cell::MetaCellSamples& out) const {
  // Where the band holds no leaf, no voxel is within its half-width of the other
  // side, so the whole block is on the side of its first voxel.
  const float outside = static_cast<float>(halfWidth_);
  const MaskGrid& mask = closed_ ? *closed_ : mask_;
  auto accessor = mask.getConstAccessor();
  readMetaCell(held_, index, size_, out, apron_, [&](const std::array<int, 3>& block) {
    return accessor.isValueOn(openvdb::Coord(block[0], block[1], block[2])) ? -outside : outside;
  });
}

SlabBand::Figures SlabBand::figures() const {
  Figures figures = figures_;
  for (int a = 0; a < 3; ++a) {
    figures.bboxMin[a] = figures.activeVoxels > 0 ? activeBox_.min()[a] : 0;
    figures.bboxMax[a] = figures.activeVoxels > 0 ? activeBox_.max()[a] : 0;
  }
  if (figures.activeVoxels == 0) figures.minValue = figures.maxValue = 0;
  return figures;
}

void SlabBand::dropBelow(int z) {
  std::vector<openvdb::Coord> origins;
  for (auto leaf = band_->tree().cbeginLeaf(); leaf; ++leaf)
    if (leaf->origin().z() + kLeafDim <= z) origins.push_back(leaf->origin());
  for (const openvdb::Coord& origin : origins) {
    const std::unique_ptr<FieldLeaf> leaf(band_->tree().stealNode<FieldLeaf>(origin, band_->background(), false));
    if (leaf) heldBytes_ -= static_cast<std::int64_t>(leaf->memUsage());
  }
}

}  // namespace isovdb::volume
