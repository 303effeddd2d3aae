// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vector_slice_stream.h
/// @brief An in-memory SliceStream for tests (dense volumes built in code).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isovdb/io/slice_stream.h"

namespace isovdb::test {

class VectorSliceStream : public io::SliceStream {
 public:
  VectorSliceStream(std::array<std::int64_t, 3> dims, std::vector<float> values, std::string name = "memory")
      : values_(std::move(values)), name_(std::move(name)) {
    header_.dims = dims;
    header_.sampleType = io::SampleType::Float32;
  }
  /// Samples f(x, y, z) at every voxel.
  static VectorSliceStream fromFunction(std::array<std::int64_t, 3> dims,
                                        const std::function<float(int, int, int)>& f) {
    std::vector<float> values(static_cast<std::size_t>(dims[0] * dims[1] * dims[2]));
    std::size_t i = 0;
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) values[i++] = f(x, y, z);
    return VectorSliceStream(dims, std::move(values));
  }

  const std::string& source() const override { return name_; }
  const io::VolumeHeader& header() const override { return header_; }
  void readSlice(float* out) override {
    const std::size_t n = static_cast<std::size_t>(header_.sliceSamples());
    std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(next_ * n), n, out);
    ++next_;
  }
  std::int64_t nextSlice() const override { return next_; }

  io::VolumeHeader& mutableHeader() { return header_; }
  const std::vector<float>& values() const { return values_; }
  float at(int x, int y, int z) const {
    return values_[static_cast<std::size_t>((z * header_.dims[1] + y) * header_.dims[0] + x)];
  }
  /// A fresh stream over the same samples (streams are read once).
  VectorSliceStream rewound() const {
    VectorSliceStream copy(header_.dims, values_, name_);
    copy.header_ = header_;
    return copy;
  }

 private:
  io::VolumeHeader header_;
  std::vector<float> values_;
  std::string name_;
  std::int64_t next_ = 0;
};

}  // namespace isovdb::test
