// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dense_slice_stream.h
/// @brief A SliceStream over the bytes of a dense volume (raw, NRRD or MetaImage
///        data, plain or inflated), converted to float one z-slice at a time.
///
/// Memory: one slice of file bytes plus the byte stream's buffer; never the volume.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "isovdb/io/lazy_buffer.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// Validates `header.dims` and returns the volume's size in bytes
/// (dims product × sample size).
/// @param[in] source the file, for messages.
/// @param[in] dimsField the field that declared the dims ("DimSize", "sizes", "dims"), for messages.
/// @throw InputError naming the file and the field when a dim is not positive or the
///        voxel count or byte size overflows a 64-bit integer.
std::int64_t checkedVolumeBytes(const VolumeHeader& header, const std::string& source, std::string_view dimsField);

/// Reads the slices of a volume whose samples follow each other in `bytes`
/// (x fastest, then y, then z), in the type and byte order of `header`.
class DenseSliceStream final : public SliceStream {
 public:
  /// @param[in] source the file the user named (the header for detached data), for messages.
  /// @param[in] header dims, sample type, byte order and geometry; dims must be valid
  ///            (see checkedVolumeBytes()).
  /// @param[in] bytes positioned at the first sample.
  /// @throw InputError when the dims are invalid.
  DenseSliceStream(std::string source, const VolumeHeader& header, std::unique_ptr<ByteStream> bytes);

  const std::string& source() const override { return source_; }
  const VolumeHeader& header() const override { return header_; }

  /// Reads slice nextSlice() into `out` (header().sliceSamples() floats).
  /// After the last slice, checks that compressed data ends where the header says.
  /// @throw InputError "'<file>': voxel (x, y, z) is NaN" (or +Inf/-Inf, or out of
  ///        the float range for float64 data); the ByteStream's InputError when the
  ///        data ends early or is corrupt; IoError when the OS read fails;
  ///        std::out_of_range when all slices were already read.
  void readSlice(float* out) override;

  std::int64_t nextSlice() const override { return nextSlice_; }

  /// Moves past `count` slices without converting them: a file region seeks, an
  /// inflating stream inflates without keeping (a distributed run's slab starts there).
  /// @throw InputError when the data ends first; std::out_of_range past the last slice.
  void skipSlices(std::int64_t count) override;

 private:
  std::string source_;
  VolumeHeader header_;
  std::unique_ptr<ByteStream> bytes_;
  std::int64_t totalBytes_ = 0;
  std::int64_t nextSlice_ = 0;
  LazyBuffer<std::byte> sliceBytes_;  // pages touched only as the data arrives
};

}  // namespace isovdb::io
