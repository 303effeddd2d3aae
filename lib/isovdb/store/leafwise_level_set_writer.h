// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file leafwise_level_set_writer.h
/// @brief A level-set `.vdb` file written from leaves that arrive a batch at a
///        time, in any order, so the narrow band is never held whole.
///
/// OpenVDB's writer needs the whole tree in memory: a file holds the tree's
/// topology (every node's masks and tile values) before any voxel value. Here
/// each leaf's voxel block is serialised by OpenVDB's own LeafNode::writeBuffers
/// as soon as it arrives, into a spill file beside the output, and the leaf is
/// freed; only its origin, value mask and first/last values stay (about 90
/// bytes against 2 KiB). commit() then writes the file as io::Archive does (header,
/// grid descriptor, metadata with the delayed-load table, transform), with the
/// topology made from those records and the buffers copied from the spill in
/// tree order. The tree it describes is exactly the one the
/// in-memory path builds (addLeaf, tools::signedFloodFill, tools::pruneLevelSet):
/// same nodes, tiles, values and bytes per node, so readers cannot tell them apart.
/// Heavy (includes openvdb.h): include it only from .cc files.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "isovdb/io/atomic_file.h"
#include "isovdb/progress.h"
#include "isovdb/volume/grids.h"

namespace isovdb::store {

/// What was written, for the statistics report.
struct LevelSetFileSummary {
  std::int64_t leafCount = 0;                                ///< leaves with active voxels (the file's leaves)
  std::int64_t activeVoxels = 0;                             ///< voxels in the band
  std::int64_t spillBytes = 0;                               ///< serialised leaf blocks (the spill file's size)
  std::int64_t fileBytes = 0;                                ///< size of the .vdb file
  std::array<int, 3> bboxMin{0, 0, 0}, bboxMax{-1, -1, -1};  ///< active voxels, index space
  float minValue = 0.f, maxValue = 0.f;                      ///< band values, in voxels
};

class LeafwiseLevelSetWriter {
 public:
  struct Options {
    std::string gridName = "sdf";
    std::string source;  ///< provenance, written as `isovdb_source`
  };

  /// Prepares `path` (written through a temporary beside it, renamed on commit)
  /// and the spill file beside it. `halfWidth` is the band's half-width in voxels
  /// (the leaves' inactive values are ±halfWidth); values are written in world
  /// units like writeVdb.
  /// @throw IoError naming `path` when its folder is missing or not writable.
  LeafwiseLevelSetWriter(std::filesystem::path path, float halfWidth, const volume::Geometry& geometry,
                         Options options);
  /// Removes the spill file, and the temporary unless commit() succeeded.
  ~LeafwiseLevelSetWriter();
  LeafwiseLevelSetWriter(const LeafwiseLevelSetWriter&) = delete;
  LeafwiseLevelSetWriter& operator=(const LeafwiseLevelSetWriter&) = delete;

  /// Serialises and frees the leaves. Thread-safe. Every origin must come once,
  /// with inactive values already flood-filled to ±halfWidth.
  /// @throw IoError when the spill file cannot be written (disk full, ...).
  void add(std::vector<std::unique_ptr<volume::FieldLeaf>>&& leaves);

  /// Writes the .vdb file and renames it onto the path.
  /// @throw IoError on a failed write; std::logic_error when an origin came twice.
  LevelSetFileSummary commit(Interrupter* interrupter = nullptr);

  /// Where each leaf's serialised block is, and what the topology needs of it.
  struct LeafRecord {
    openvdb::Coord origin;
    openvdb::util::NodeMask<3> valueMask;
    float first = 0.f, last = 0.f;  ///< values at the leaf's first and last voxel (flood fill, pruning)
    std::uint64_t offset = 0;       ///< in the spill file
    std::uint32_t bytes = 0;        ///< 0 when the leaf has no active voxel (it becomes a tile)
    /// What a delayed-loading reader needs to skip the block (io::DelayedLoadMetadata):
    /// the mask-compression byte and the compressed size, as io::Archive records them.
    std::int8_t maskCompression = 0;
    std::int64_t compressedBytes = 0;
  };

 private:
  std::filesystem::path path_;
  io::AtomicFile target_;
  std::filesystem::path spillPath_;
  std::ofstream spill_;
  float scale_, background_;  ///< voxel -> written units; the background in written units
  volume::Geometry geometry_;
  Options options_;
  std::uint32_t compression_;  ///< flags the leaf blocks were serialised with
  std::mutex mutex_;
  std::deque<LeafRecord> records_;  // a deque: no doubling copy while chunks are in flight
  LevelSetFileSummary summary_;
  std::uint64_t spillOffset_ = 0;
};

}  // namespace isovdb::store
