// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/dense_slice_stream.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "isovdb/errors.h"

namespace isovdb::io {

namespace {

constexpr char kAxisNames[3] = {'x', 'y', 'z'};

std::string describeDims(const std::array<std::int64_t, 3>& dims) {
  return std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
}

std::string describeValue(float value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
  return std::to_string(value);
}

}  // namespace

std::int64_t checkedVolumeBytes(const VolumeHeader& header, const std::string& source, std::string_view dimsField) {
  const std::string where = "'" + source + "': " + std::string(dimsField);
  for (int axis = 0; axis < 3; ++axis) {
    if (header.dims[axis] <= 0)
      throw InputError(where + ": " + kAxisNames[axis] + " size must be positive, got " +
                       std::to_string(header.dims[axis]));
  }
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  std::int64_t count = 1;
  for (int axis = 0; axis < 3; ++axis) {
    if (count > kMax / header.dims[axis])
      throw InputError(where + ": " + describeDims(header.dims) + " voxels overflow a 64-bit count");
    count *= header.dims[axis];
  }
  const auto size = static_cast<std::int64_t>(sampleSize(header.sampleType));
  if (count > kMax / size)
    throw InputError(where + ": " + describeDims(header.dims) + " " + std::string(sampleTypeName(header.sampleType)) +
                     " samples overflow a 64-bit byte size");
  return count * size;
}

DenseSliceStream::DenseSliceStream(std::string source, const VolumeHeader& header, std::unique_ptr<ByteStream> bytes)
    : source_(std::move(source)), header_(header), bytes_(std::move(bytes)) {
  totalBytes_ = checkedVolumeBytes(header_, source_, "dims");
}

void DenseSliceStream::readSlice(float* out) {
  if (nextSlice_ >= header_.dims[2])
    throw std::out_of_range("'" + source_ + "': all " + std::to_string(header_.dims[2]) + " slices were read");
  const auto samples = static_cast<std::size_t>(header_.sliceSamples());
  const std::size_t size = samples * sampleSize(header_.sampleType);
  if (sliceBytes_.size() != size) sliceBytes_.resize(size);
  bytes_->readExact(sliceBytes_.data(), size, totalBytes_);

  const std::int64_t bad = convertSamples(sliceBytes_.data(), header_.sampleType, header_.bigEndian, samples, out);
  const std::string voxelPrefix = "'" + source_ + "': voxel (";
  const auto voxel = [&](std::int64_t index) {
    return voxelPrefix + std::to_string(index % header_.dims[0]) + ", " + std::to_string(index / header_.dims[0]) +
           ", " + std::to_string(nextSlice_) + ")";
  };
  if (bad >= 0)
    throw InputError(voxel(bad) + " is " + describeValue(out[bad]) + " (" +
                     std::string(sampleTypeName(header_.sampleType)) + " samples must be finite)");
  if (header_.sampleType == SampleType::Float64) {
    // Finite doubles beyond the float range became +-Inf in the conversion.
    for (std::size_t i = 0; i < samples; ++i) {
      if (std::isfinite(out[i])) continue;
      std::array<std::byte, sizeof(double)> raw;
      std::memcpy(raw.data(), sliceBytes_.data() + i * sizeof(double), sizeof(double));
      if (header_.bigEndian != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
      double value = 0;
      std::memcpy(&value, raw.data(), sizeof(double));
      std::ostringstream text;
      text << value;
      throw InputError(voxel(static_cast<std::int64_t>(i)) + " = " + text.str() + " exceeds the float range");
    }
  }
  ++nextSlice_;
  if (nextSlice_ == header_.dims[2]) bytes_->finish(totalBytes_);
}

void DenseSliceStream::skipSlices(std::int64_t count) {
  if (count <= 0) return;
  if (nextSlice_ + count > header_.dims[2])
    throw std::out_of_range("'" + source_ + "': skipping " + std::to_string(count) + " slices from slice " +
                            std::to_string(nextSlice_) + " of " + std::to_string(header_.dims[2]));
  bytes_->skip(count * header_.sliceSamples() * static_cast<std::int64_t>(sampleSize(header_.sampleType)));
  nextSlice_ += count;
  if (nextSlice_ == header_.dims[2]) bytes_->finish(totalBytes_);
}

}  // namespace isovdb::io
