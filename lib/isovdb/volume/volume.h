// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file volume.h
/// @brief The sparse volume every stage after ingest works on: an OpenVDB grid
///        in voxel index space plus the transform to world space.
///
/// This header is light on purpose: it only forward-declares openvdb::GridBase.
/// Code that touches voxels includes "isovdb/volume/grids.h" in its .cc file.
///
/// Conventions: the grid's own transform is the identity (voxel index space);
/// distances of a DistanceField are in voxels, NEGATIVE inside. `geometry`
/// maps index to world (world = origin + spacing * index) and is applied once,
/// when a mesh or a .vdb file is written.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include <openvdb/version.h>

#include "isovdb/named_values.h"

namespace openvdb {
OPENVDB_USE_VERSION_NAMESPACE
namespace OPENVDB_VERSION_NAME {
class GridBase;
}
}  // namespace openvdb

namespace isovdb::volume {

/// What the grid holds.
enum class VolumeKind {
  Mask,           ///< openvdb::BoolGrid: active (and true) = inside the object
  Scalar,         ///< openvdb::FloatGrid: a sampled scalar field (density, amplitude, ...)
  DistanceField,  ///< openvdb::FloatGrid, GRID_LEVEL_SET: narrow-band signed distance in voxels
};

inline constexpr NameTable<VolumeKind, 3> kVolumeKindNames{
    {{VolumeKind::Mask, "mask"}, {VolumeKind::Scalar, "scalar"}, {VolumeKind::DistanceField, "distance field"}}};
constexpr std::string_view volumeKindName(VolumeKind kind) { return nameOf(kVolumeKindNames, kind); }

/// Axis-aligned index-to-world map: world = origin + spacing * index.
struct Geometry {
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<double, 3> origin{0.0, 0.0, 0.0};

  bool isUniform() const { return spacing[0] == spacing[1] && spacing[1] == spacing[2]; }
};

/// Refuses a geometry whose world coordinates cannot be written as mesh vertices
/// (float): a non-finite or non-positive spacing, a non-finite origin, or one so
/// large that an index within int32 maps beyond float's range.
/// @throw InputError naming `source` and the axis.
void checkGeometry(const Geometry& geometry, const std::string& source);

/// Figures `isovdb info` and the statistics report about a grid.
struct GridStats {
  std::int64_t activeVoxels = 0;        ///< voxels inside (mask) or stored (scalar, SDF band), tiles expanded
  std::int64_t leafCount = 0;           ///< 8^3 leaf nodes
  std::int64_t tileCount = 0;           ///< active tiles at any level (homogeneous blocks)
  std::int64_t memoryBytes = 0;         ///< openvdb's memUsage() of the tree
  std::array<int, 3> bboxMin{0, 0, 0};  ///< active bounding box, index space, inclusive
  std::array<int, 3> bboxMax{-1, -1, -1};
  float minValue = 0.f, maxValue = 0.f;  ///< value range (Scalar and DistanceField only)
  float background = 0.f;                ///< value of inactive space (Scalar and DistanceField only)
};

/// A sparse volume: one OpenVDB grid, its kind and its world geometry.
/// Copies share the grid (shallow) and its stats(); a grid is not modified once a Volume holds
/// it (an edited grid gets a new Volume) but for SlabBand's band, which keeps its own figures().
class Volume {
 public:
  Volume() = default;
  /// @throw InputError when checkGeometry refuses `geometry`.
  Volume(VolumeKind kind, std::shared_ptr<openvdb::GridBase> grid, Geometry geometry, std::string name);

  VolumeKind kind() const { return kind_; }
  const Geometry& geometry() const { return geometry_; }
  /// Name used for the grid in .vdb files and in messages (e.g. the source file).
  const std::string& name() const { return name_; }
  bool valid() const { return grid_ != nullptr; }

  const std::shared_ptr<openvdb::GridBase>& grid() const { return grid_; }

  /// Counts active voxels, leaves and tiles and measures memory and the value range: walks
  /// the tree on the first call only (an extract asks three times; a dense 512^3 field's
  /// range alone took 0.1 s a walk).
  GridStats stats() const;

  /// Records the range of the active values, which the code that filled the grid saw
  /// (ingestScalar): stats() then does not walk every value for it. Call before stats().
  void setValueRange(float min, float max) { stats_->knownRange = {min, max}; }

 private:
  struct StatsOnce {
    std::once_flag once;
    GridStats stats;
    std::optional<std::pair<float, float>> knownRange;
  };

  VolumeKind kind_ = VolumeKind::Mask;
  std::shared_ptr<openvdb::GridBase> grid_;
  std::shared_ptr<StatsOnce> stats_ = std::make_shared<StatsOnce>();
  Geometry geometry_;
  std::string name_;
};

/// A copy of scalar field `volume` with every value negated, the background too, and its
/// geometry, name and metadata (the sampled box) kept: a field whose object lies below the
/// isovalue, for code that takes a scalar's inside to lie above it. A deep copy (the
/// grid's memory again); the input is left as it is.
/// @throw InputError when `volume` is not a scalar field
Volume negatedScalar(const Volume& volume);

}  // namespace isovdb::volume
