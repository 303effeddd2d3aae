// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file sample_statistics.h
/// @brief Value range, percentiles and dead-band figures of the samples a
///        SliceStream delivers, gathered while the stream is ingested (no second read).
///
/// Percentiles come from a histogram of the float bit patterns (2^20 bins of
/// signed values, 2^19 of magnitudes: 12 MiB): a percentile is the sample's
/// value truncated towards zero to 11 mantissa bits (exact for integers below
/// 2048, within 1/2048 of the value above), whatever the range; min, max,
/// counts and the active fraction are exact. NaN samples are holes (SEG-Y positions without a trace).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// What SampleStatistics found.
struct SampleSummary {
  std::int64_t samples = 0;  ///< finite samples seen
  std::int64_t holes = 0;    ///< NaN samples (no trace at that position)
  float minValue = 0.f, maxValue = 0.f;
  double clip = 0.0;               ///< the dead band asked about: |value| < clip is quiet
  std::int64_t activeSamples = 0;  ///< samples with |value| >= clip
  /// activeSamples / samples (0 when there is no sample).
  double activeFraction() const { return samples ? static_cast<double>(activeSamples) / samples : 0.0; }
};

/// Accumulates samples; memory 12 MiB whatever the volume.
class SampleStatistics {
 public:
  /// @param[in] clip the dead band to report on (|value| < clip is quiet; 0: every sample is active).
  explicit SampleStatistics(double clip);

  void add(const float* values, std::size_t count);

  const SampleSummary& summary() const { return summary_; }
  /// Value below which `percent` % of the samples lie (0 <= percent <= 100).
  float percentile(double percent) const;
  /// Same for |value| (what a --clip keeps: clip at the 90th percentile of |value|
  /// leaves about 10 % of the samples active).
  float absPercentile(double percent) const;

 private:
  SampleSummary summary_;
  std::vector<std::uint64_t> signedBins_, absBins_;
};

/// A SliceStream that passes another one's slices on and feeds them to a SampleStatistics.
class ObservedSliceStream final : public SliceStream {
 public:
  ObservedSliceStream(SliceStream& inner, SampleStatistics& statistics) : inner_(inner), statistics_(statistics) {}
  const std::string& source() const override { return inner_.source(); }
  const VolumeHeader& header() const override { return inner_.header(); }
  void readSlice(float* out) override;
  std::int64_t nextSlice() const override { return inner_.nextSlice(); }

 private:
  SliceStream& inner_;
  SampleStatistics& statistics_;
};

}  // namespace isovdb::io
