// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/volume.h"

#include <openvdb/tools/Count.h>
#include <openvdb/tools/ValueTransformer.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

void checkGeometry(const Geometry& geometry, const std::string& source) {
  // Index coordinates are int32, so |world| <= |origin| + spacing * 2^31 must stay a finite float.
  constexpr double kLargestIndex = 2147483648.0;
  constexpr double kLargestFloat = std::numeric_limits<float>::max();
  static constexpr char kAxes[] = "xyz";
  for (int a = 0; a < 3; ++a) {
    const double spacing = geometry.spacing[a], origin = geometry.origin[a];
    std::ostringstream problem;
    if (!std::isfinite(spacing) || spacing <= 0)
      problem << "voxel size " << spacing << " along " << kAxes[a] << " is not a positive finite number";
    else if (!std::isfinite(origin))
      problem << "origin " << origin << " along " << kAxes[a] << " is not a finite number";
    else if (std::abs(origin) + spacing * kLargestIndex > kLargestFloat)
      problem << "origin " << origin << " and voxel size " << spacing << " along " << kAxes[a]
              << " put world coordinates beyond float's range (mesh vertices are float)";
    if (!problem.str().empty()) throw InputError("'" + source + "': " + problem.str());
  }
}

Volume::Volume(VolumeKind kind, std::shared_ptr<openvdb::GridBase> grid, Geometry geometry, std::string name)
    : kind_(kind), grid_(std::move(grid)), geometry_(geometry), name_(std::move(name)) {
  checkGeometry(geometry_, name_);
}

const MaskGrid& maskGrid(const Volume& volume) {
  if (volume.kind() != VolumeKind::Mask || !volume.grid())
    throw InputError("'" + volume.name() + "': expected a mask volume, got a " +
                     std::string(volumeKindName(volume.kind())));
  return static_cast<const MaskGrid&>(*volume.grid());
}

FieldGrid::Ptr fieldGridPtr(const Volume& volume) {
  if (volume.kind() == VolumeKind::Mask || !volume.grid())
    throw InputError("'" + volume.name() + "': expected a scalar or distance volume, got a mask");
  return std::static_pointer_cast<FieldGrid>(volume.grid());
}

const FieldGrid& fieldGrid(const Volume& volume) { return *fieldGridPtr(volume); }

namespace {

template <typename TreeT>
GridStats treeStats(const TreeT& tree, bool withRange, const std::optional<std::pair<float, float>>& knownRange) {
  GridStats stats;
  stats.activeVoxels = static_cast<std::int64_t>(tree.activeVoxelCount());
  stats.leafCount = static_cast<std::int64_t>(tree.leafCount());
  stats.tileCount = static_cast<std::int64_t>(tree.activeTileCount());
  stats.memoryBytes = static_cast<std::int64_t>(tree.memUsage());
  openvdb::CoordBBox bbox;
  if (tree.evalActiveVoxelBoundingBox(bbox)) {
    for (int a = 0; a < 3; ++a) {
      stats.bboxMin[a] = bbox.min()[a];
      stats.bboxMax[a] = bbox.max()[a];
    }
  }
  if constexpr (std::is_same_v<typename TreeT::ValueType, float>) {
    stats.background = tree.background();
    if (withRange && stats.activeVoxels > 0) {
      if (knownRange) {
        std::tie(stats.minValue, stats.maxValue) = *knownRange;
      } else {
        const auto extrema = openvdb::tools::minMax(tree);
        stats.minValue = extrema.min();
        stats.maxValue = extrema.max();
      }
    }
  }
  return stats;
}

}  // namespace

GridStats Volume::stats() const {
  if (!grid_) return {};
  std::call_once(stats_->once, [this] {
    stats_->stats = kind_ == VolumeKind::Mask ? treeStats(maskGrid(*this).tree(), false, std::nullopt)
                                              : treeStats(fieldGrid(*this).tree(), true, stats_->knownRange);
  });
  return stats_->stats;
}

Volume negatedScalar(const Volume& volume) {
  if (volume.kind() != VolumeKind::Scalar)
    throw InputError("'" + volume.name() + "': only a scalar field can be read with its inside below the isovalue");
  const FieldGrid::Ptr grid = fieldGrid(volume).deepCopy();
  const float background = grid->background();
  openvdb::tools::foreach (grid->beginValueAll(), [](const FieldGrid::ValueAllIter& it) { it.setValue(-*it); });
  grid->tree().root().setBackground(-background, /*updateChildNodes=*/false);  // inactive values negated above
  return Volume(VolumeKind::Scalar, grid, volume.geometry(), volume.name());
}

}  // namespace isovdb::volume
