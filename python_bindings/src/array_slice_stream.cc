// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "array_slice_stream.h"

#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::python {

ArraySliceStream::ArraySliceStream(const std::byte* data, std::array<std::int64_t, 3> shape, io::SampleType type,
                                   bool bigEndian, std::array<double, 3> spacing, std::array<double, 3> origin)
    : data_(data) {
  header_.sampleType = type;
  header_.bigEndian = bigEndian;
  header_.gridAxis = {2, 1, 0};
  for (int a = 0; a < 3; ++a) {
    header_.dims[a] = shape[2 - a];
    header_.spacing[a] = spacing[2 - a];
    header_.origin[a] = origin[2 - a];
  }
}

void ArraySliceStream::readSlice(float* out) {
  if (nextSlice_ >= header_.dims[2]) throw InputError(source_ + ": read past the last x-plane");
  const std::size_t count = static_cast<std::size_t>(header_.sliceSamples());
  const std::byte* plane = data_ + static_cast<std::size_t>(nextSlice_) * count * io::sampleSize(header_.sampleType);
  const std::int64_t bad = io::convertSamples(plane, header_.sampleType, header_.bigEndian, count, out);
  if (bad >= 0) {
    const std::int64_t z = bad % header_.dims[0], y = bad / header_.dims[0];
    const float value = out[bad];
    throw InputError(source_ + ": sample [" + std::to_string(nextSlice_) + ", " + std::to_string(y) + ", " +
                     std::to_string(z) + "] is " + (std::isnan(value) ? "NaN" : "infinite") +
                     " (every sample must be finite)");
  }
  ++nextSlice_;
}

}  // namespace isovdb::python
