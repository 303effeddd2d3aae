// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file array_slice_stream.h
/// @brief A C-contiguous numpy array [x, y, z] read by the library's streaming ingest
///        like any dense file, without copying it first.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "isovdb/io/slice_stream.h"

namespace isovdb::python {

/// Streams a C-contiguous array indexed [x, y, z] (z fastest in memory). The stream's
/// slices are the array's x-planes (contiguous), so its axes are (z, y, x) and
/// VolumeHeader::gridAxis maps them back: grid voxel (x, y, z) = array[x, y, z].
/// The array must outlive the stream (it is read without the GIL).
class ArraySliceStream final : public io::SliceStream {
 public:
  /// @param[in] shape  the array's shape (x, y, z), each > 0
  /// @param[in] xFastest  the array is Fortran-ordered (x varies fastest, like a raw file's
  ///                      samples and a [z, y, x] stack's transpose): it is read in z-planes;
  ///                      else C-ordered (z fastest), read in x-planes
  ArraySliceStream(const std::byte* data, std::array<std::int64_t, 3> shape, io::SampleType type, bool bigEndian,
                   std::array<double, 3> spacing, std::array<double, 3> origin, bool xFastest = false);

  const std::string& source() const override { return source_; }
  const io::VolumeHeader& header() const override { return header_; }
  /// @throw InputError "numpy array: sample [x, y, z] is nan" for a non-finite sample.
  void readSlice(float* out) override;
  std::int64_t nextSlice() const override { return nextSlice_; }

 private:
  const std::byte* data_;
  std::string source_ = "numpy array";
  io::VolumeHeader header_;
  std::int64_t nextSlice_ = 0;
  bool xFastest_ = false;
};

}  // namespace isovdb::python
