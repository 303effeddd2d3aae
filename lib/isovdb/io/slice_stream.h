// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slice_stream.h
/// @brief A dense volume read z-slice by z-slice, so nothing holds the whole volume.
///
/// Coordinates: voxel (x, y, z) with x fastest, as in raw, NRRD and MetaImage
/// files. `spacing` and `origin` map index space to world space:
/// world = origin + spacing * index (axis-aligned; rotations are not supported).
/// A stream's axes are the file's storage order; `gridAxis` says which axis of
/// the sparse grid each one becomes (the identity for dense files; SEG-Y stores
/// traces, samples fastest, and its samples become the grid's z).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "isovdb/io/sample_type.h"

namespace isovdb::io {

/// What a dense volume file declares about its samples.
struct VolumeHeader {
  std::array<std::int64_t, 3> dims{0, 0, 0};  ///< samples along x, y, z (each > 0)
  SampleType sampleType = SampleType::UInt8;
  bool bigEndian = false;                        ///< byte order of the file's samples
  std::array<double, 3> spacing{1.0, 1.0, 1.0};  ///< world units per voxel
  std::array<double, 3> origin{0.0, 0.0, 0.0};   ///< world position of voxel (0,0,0)
  /// Grid axis (0 = x, 1 = y, 2 = z) of each stream axis: a permutation of {0, 1, 2}.
  /// dims, spacing and origin are per stream axis; ingest permutes them.
  std::array<int, 3> gridAxis{0, 1, 2};

  std::int64_t sliceSamples() const { return dims[0] * dims[1]; }
};

/// Streams the slices of a dense volume in increasing z.
class SliceStream {
 public:
  virtual ~SliceStream() = default;

  /// The file (or generator) the slices come from; used in error messages.
  virtual const std::string& source() const = 0;
  virtual const VolumeHeader& header() const = 0;

  /// Reads the next z-slice, converted to float, into `out`
  /// (header().sliceSamples() values, x fastest).
  /// @throw InputError when the data ends early or holds NaN/Inf (message names
  ///        the file and the voxel); IoError when the OS read fails.
  virtual void readSlice(float* out) = 0;

  /// Index of the next slice readSlice() returns.
  virtual std::int64_t nextSlice() const = 0;

  /// True when slices [first, first + count) hold no sample at all (outside a
  /// SliceWindow): ingest then moves past them with skipSlices() instead of reading
  /// and classifying them.
  virtual bool blank(std::int64_t first, std::int64_t count) const {
    (void)first;
    (void)count;
    return false;
  }

  /// Moves past the next `count` slices without returning them (by default: reads and
  /// discards them). Inline, as every other member: generators outside the library
  /// (data/generators) derive from this class without linking it.
  virtual void skipSlices(std::int64_t count) {
    if (count <= 0) return;
    std::vector<float> discarded(static_cast<std::size_t>(header().sliceSamples()));
    for (std::int64_t i = 0; i < count; ++i) readSlice(discarded.data());
  }
};

}  // namespace isovdb::io
