// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file interface_band.h
/// @brief The narrow band of a mask built from its interface (the default distance
///        field, `--distance interface`). Heavy (includes openvdb.h through
///        grids.h): include it only from .cc files.
///
/// A voxel is an *interface voxel* when one of its six face neighbours lies on
/// the other side of the mask. Each interface voxel gets a sub-voxel distance
/// to the surface and a normal from the mask blurred by a small Gaussian (the
/// blur averages the staircase of a voxelised surface into the plane it
/// samples: on analytic spheres and tori the mesh lies 0.05-0.08 voxel from the
/// true surface on average, against 0.09-0.10 for topologyToLevelSet +
/// sdfToSdf). Every other voxel of the band takes the value of the tangent plane
/// of its nearest interface voxel, found by an exact Euclidean nearest-voxel
/// transform (three separable passes, truncated at halfWidth + 1). Signs are
/// the mask's, always: a value never crosses zero against the voxel's side, so
/// the digital topology of the mask is the topology of the field.
///
/// Each value depends on the mask within halfWidth + 4 voxels only, so the band
/// is computed in independent chunks with an apron of that width: the result is
/// the same bit for bit for every chunk size and thread count, the work follows
/// the interface (chunks without one cost a few probes) and the memory is one
/// chunk's buffers per thread, about 8 bytes per voxel of (chunk + 2 apron)^3 (the
/// mask itself is read from its leaves' bits, never copied).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "isovdb/volume/band_chunks.h"

namespace isovdb::volume {

/// The band of `mask` (already closed, if closing was asked for) in cubes of
/// `chunkSize` voxels, chunks in parallel. Every leaf of the band that holds an
/// active voxel (|value| < halfWidth) goes to `sink` exactly once, inactive
/// values set to -halfWidth inside and +halfWidth outside. Returns the number of
/// chunks that held an interface.
/// @throw Interrupted on cancellation.
std::size_t computeInterfaceBand(const MaskGrid& mask, int halfWidth, int chunkSize, const BandLeafSink& sink,
                                 Interrupter* interrupter);

/// The same band, computed on demand in slabs along z: a caller that consumes the
/// band slab by slab (volume/slab_band.h) never holds all of it. Chunk cubes start
/// at multiples of chunkSize, as in computeInterfaceBand, so the values are the same.
class InterfaceBandChunks {
 public:
  InterfaceBandChunks(const MaskGrid& mask, int halfWidth, int chunkSize);
  ~InterfaceBandChunks();
  InterfaceBandChunks(const InterfaceBandChunks&) = delete;
  InterfaceBandChunks& operator=(const InterfaceBandChunks&) = delete;

  int chunkSize() const;
  /// Chunks whose region may hold an interface.
  std::size_t chunkCount() const;
  /// [first z, last z + chunkSize) of those chunks; nullopt when there are none.
  std::optional<std::pair<int, int>> zRange() const;
  /// Computes the chunks whose cube starts at z in [zBegin, zEnd), in parallel,
  /// handing their leaves to `sink` as computeInterfaceBand does; `chunkDone` (optional)
  /// runs after each chunk, one call at a time. Returns the chunks that held an interface.
  std::size_t compute(int zBegin, int zEnd, const BandLeafSink& sink, const std::function<void()>& chunkDone = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isovdb::volume
