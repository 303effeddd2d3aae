// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/slice_window.h"

#include <algorithm>
#include <limits>
#include <string>

#include "isovdb/errors.h"

namespace isovdb::io {

SliceWindowStream::SliceWindowStream(SliceStream& inner, const SliceWindow& window) : inner_(inner), window_(window) {
  const auto& axes = inner.header().gridAxis;
  zAxis_ = static_cast<int>(std::find(axes.begin(), axes.end(), 2) - axes.begin());
}

bool SliceWindowStream::blank(std::int64_t first, std::int64_t count) const {
  if (zAxis_ != 2) return false;
  return first + count <= window_.begin || first >= window_.end;
}

void SliceWindowStream::skipSlices(std::int64_t count) {
  // Past the window's end nothing more is read: the file may stop being read there.
  const std::int64_t wanted = zAxis_ == 2 ? std::min(next_ + count, window_.end) : next_ + count;
  if (wanted > inner_.nextSlice()) inner_.skipSlices(wanted - inner_.nextSlice());
  next_ += count;
}

void SliceWindowStream::readSlice(float* out) {
  const VolumeHeader& h = header();
  const std::int64_t n = h.sliceSamples();
  constexpr float kHole = std::numeric_limits<float>::quiet_NaN();
  if (zAxis_ == 2 && (next_ < window_.begin || next_ >= window_.end)) {
    skipSlices(1);
    std::fill(out, out + n, kHole);
    return;
  }
  if (inner_.nextSlice() < next_) inner_.skipSlices(next_ - inner_.nextSlice());
  inner_.readSlice(out);
  ++next_;
  if (zAxis_ == 2) return;
  // Grid z runs along a stream row (x) or across rows (y): blank what lies outside.
  const std::int64_t nx = h.dims[0], ny = h.dims[1];
  const std::int64_t lo = std::clamp<std::int64_t>(window_.begin, 0, h.dims[zAxis_]);
  const std::int64_t hi = std::clamp<std::int64_t>(window_.end, lo, h.dims[zAxis_]);
  if (zAxis_ == 0) {
    for (std::int64_t y = 0; y < ny; ++y) {
      float* row = out + y * nx;
      std::fill(row, row + lo, kHole);
      std::fill(row + hi, row + nx, kHole);
    }
  } else {
    std::fill(out, out + lo * nx, kHole);
    std::fill(out + hi * nx, out + ny * nx, kHole);
  }
}

PlacedSliceStream::PlacedSliceStream(SliceStream& inner, std::int64_t first, std::int64_t total)
    : inner_(inner), header_(inner.header()), first_(first) {
  if (header_.gridAxis[2] != 2)
    throw InputError("'" + inner.source() + "': a placed slab needs its slices along grid z");
  if (first < 0 || first + header_.dims[2] > total)
    throw InputError("'" + inner.source() + "': a slab of " + std::to_string(header_.dims[2]) + " slices at " +
                     std::to_string(first) + " does not fit in " + std::to_string(total) + " slices");
  header_.dims[2] = total;
}

bool PlacedSliceStream::blank(std::int64_t first, std::int64_t count) const {
  return first + count <= first_ || first >= first_ + inner_.header().dims[2];
}

void PlacedSliceStream::skipSlices(std::int64_t count) {
  const std::int64_t end = std::min(next_ + count, first_ + inner_.header().dims[2]);
  const std::int64_t innerTarget = end - first_;
  if (innerTarget > inner_.nextSlice()) inner_.skipSlices(innerTarget - inner_.nextSlice());
  next_ += count;
}

void PlacedSliceStream::readSlice(float* out) {
  if (blank(next_, 1)) {
    skipSlices(1);
    std::fill(out, out + header_.sliceSamples(), std::numeric_limits<float>::quiet_NaN());
    return;
  }
  inner_.readSlice(out);
  ++next_;
}

}  // namespace isovdb::io
