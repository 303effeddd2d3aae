// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "array_slice_stream.h"

#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::python {

ArraySliceStream::ArraySliceStream(const std::byte* data, std::array<std::int64_t, 3> shape, io::SampleType type,
                                   bool bigEndian, std::array<double, 3> spacing, std::array<double, 3> origin,
                                   bool xFastest)
    : data_(data), xFastest_(xFastest) {
  header_.sampleType = type;
  header_.bigEndian = bigEndian;
  // The stream's axes in memory order, fastest first (a raw file's are x, y, z).
  header_.gridAxis = xFastest ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{2, 1, 0};
  for (int a = 0; a < 3; ++a) {
    const auto axis = static_cast<std::size_t>(header_.gridAxis[a]);
    header_.dims[a] = shape[axis];
    header_.spacing[a] = spacing[axis];
    header_.origin[a] = origin[axis];
  }
}

void ArraySliceStream::readSlice(float* out) {
  if (nextSlice_ >= header_.dims[2]) throw InputError(source_ + ": read past the last x-plane");
  const std::size_t count = static_cast<std::size_t>(header_.sliceSamples());
  const std::byte* plane = data_ + static_cast<std::size_t>(nextSlice_) * count * io::sampleSize(header_.sampleType);
  const std::int64_t bad = io::convertSamples(plane, header_.sampleType, header_.bigEndian, count, out);
  if (bad >= 0) {
    const std::int64_t fast = bad % header_.dims[0], middle = bad / header_.dims[0];
    const std::array<std::int64_t, 3> xyz = xFastest_ ? std::array<std::int64_t, 3>{fast, middle, nextSlice_}
                                                      : std::array<std::int64_t, 3>{nextSlice_, middle, fast};
    const float value = out[bad];
    throw InputError(source_ + ": sample [" + std::to_string(xyz[0]) + ", " + std::to_string(xyz[1]) + ", " +
                     std::to_string(xyz[2]) + "] is " + (std::isnan(value) ? "NaN" : "infinite") +
                     " (every sample must be finite)");
  }
  ++nextSlice_;
}

}  // namespace isovdb::python
