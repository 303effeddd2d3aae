// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slice_window.h
/// @brief A volume seen through a window along the grid's z axis: samples outside
///        [begin, end) read as holes (NaN: outside a mask, inactive in a scalar field),
///        so one task of a distributed run (isovdb.distributed) ingests only its slab of
///        meta-cell layers and the halo the distance field needs, and its memory follows
///        the slab, not the volume.
///
/// The file's dims, spacing and origin are kept, so the Volume keeps the whole volume's
/// index space and sampled box: the slab's meta-cells are the whole run's, samples at
/// the same places. Where the file's slices are grid z (raw, NRRD, MetaImage), slices
/// outside the window are skipped (blank()), and none after it is read; where grid z is
/// another stream axis (SEG-Y: samples along a trace), every slice is read and the
/// samples outside the window are blanked.
#pragma once

#include <cstdint>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// Grid z range [begin, end) a slab reads.
struct SliceWindow {
  std::int64_t begin = 0;
  std::int64_t end = 0;
};

class SliceWindowStream final : public SliceStream {
 public:
  /// @param inner the file's stream, read from its first slice; must outlive this object.
  SliceWindowStream(SliceStream& inner, const SliceWindow& window);

  const std::string& source() const override { return inner_.source(); }
  const VolumeHeader& header() const override { return inner_.header(); }
  void readSlice(float* out) override;
  std::int64_t nextSlice() const override { return next_; }
  bool blank(std::int64_t first, std::int64_t count) const override;
  void skipSlices(std::int64_t count) override;

 private:
  SliceStream& inner_;
  SliceWindow window_;
  int zAxis_ = 2;          ///< the stream axis that is grid z
  std::int64_t next_ = 0;  ///< slices returned or skipped
};

/// A slab of slices (`inner`, slices along grid z) placed at `first` in a volume of
/// `total` slices: the other slices are blank (holes). How a task reads its slab of a
/// chunked array (Zarr) into the whole volume's index space.
class PlacedSliceStream final : public SliceStream {
 public:
  /// @throw InputError when `inner`'s slices are not grid z or do not fit in `total`.
  PlacedSliceStream(SliceStream& inner, std::int64_t first, std::int64_t total);

  const std::string& source() const override { return inner_.source(); }
  const VolumeHeader& header() const override { return header_; }
  void readSlice(float* out) override;
  std::int64_t nextSlice() const override { return next_; }
  bool blank(std::int64_t first, std::int64_t count) const override;
  void skipSlices(std::int64_t count) override;

 private:
  SliceStream& inner_;
  VolumeHeader header_;
  std::int64_t first_ = 0;
  std::int64_t next_ = 0;
};

}  // namespace isovdb::io
