// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slab_band.h
/// @brief The distance field of a mask held one layer of meta-cells at a time, for
///        contouring a mask (`extract` in regular or adaptive mode): the interface
///        band's chunks are computed as the meta-cell layer above them needs them and
///        dropped once no later layer reads them, so the whole band is never in
///        memory (1024^3 blobs: at most 76 MiB of band at a time instead of 326).
///        The values are those of distanceField() bit for bit (the interface band does
///        not depend on its chunks), so the meshes are the same bytes. Heavy
///        (includes openvdb.h through grids.h): include it only from .cc files.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "isovdb/progress.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/interface_band.h"
#include "isovdb/volume/meta_cells.h"

namespace isovdb::volume {

class SlabBand {
 public:
  /// What the band held over the run (the figures distanceField()'s grid reports).
  struct Figures {
    std::int64_t activeVoxels = 0;
    std::int64_t leafCount = 0;  ///< leaves with an active voxel
    std::int64_t peakBytes = 0;  ///< the most leaf memory held at once (buffers included)
    std::array<int, 3> bboxMin{}, bboxMax{};
    float minValue = 0, maxValue = 0;
  };

  /// @param mask a Mask volume; kept by reference, it must outlive this object.
  /// @param apron samples read beyond each meta-cell (see readMetaCell).
  /// @pre options.method == DistanceMethod::Interface; metaCellSize a power of two.
  SlabBand(const Volume& mask, const DistanceFieldOptions& options, int metaCellSize, int apron);

  /// Layers k (meta-cells with z from k S to k S + S) that may hold the surface: [first, end).
  int firstLayer() const { return firstLayer_; }
  int endLayer() const { return endLayer_; }

  /// Computes the band layer `k` reads (what earlier calls have not computed), drops
  /// the leaves no layer from k on reads, and returns layer k's meta-cells that the
  /// surface at `iso` may cross, sorted (y, x) as partitionMetaCells sorts them.
  /// Call with k increasing.
  /// `chunkDone` (optional) runs after each chunk, one call at a time (a progress
  /// report, which may throw Interrupted).
  std::vector<MetaCellIndex> advanceTo(int k, float iso, const std::function<void()>& chunkDone = {});

  /// The samples of meta-cell `index` of the current layer. Thread-safe.
  void read(const MetaCellIndex& index, cell::MetaCellSamples& out) const;

  Figures figures() const;

 private:
  void dropBelow(int z);

  const MaskGrid& mask_;
  MaskGrid::Ptr closed_;  ///< the mask after the closing asked for, if any
  int halfWidth_, size_, apron_, margin_;
  std::unique_ptr<InterfaceBandChunks> chunks_;
  FieldGrid::Ptr band_;
  Volume held_;
  int firstLayer_ = 0, endLayer_ = 0;
  int computedEnd_ = 0;         ///< chunks starting below this z are computed
  std::int64_t heldBytes_ = 0;  ///< memory of the leaves held now
  Figures figures_;
  openvdb::CoordBBox activeBox_;
};

}  // namespace isovdb::volume
