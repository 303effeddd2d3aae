// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/sample_statistics.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace isovdb::io {

namespace {

constexpr int kDroppedBits = 12;  // 32 - 12 = 20 bits kept: sign, exponent, 11 mantissa bits
constexpr std::uint32_t kSignBit = 0x80000000u;

/// Bits of a float mapped so that unsigned order is numeric order.
std::uint32_t orderedKey(float value) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  return (bits & kSignBit) ? ~bits : bits | kSignBit;
}

constexpr std::uint32_t kDroppedMask = (1u << kDroppedBits) - 1;

/// The values of bin `bin` of orderedKey() >> kDroppedBits, truncated towards zero
/// to the bits the bin keeps (exact for integers below 2048).
float valueOfOrderedBin(std::size_t bin) {
  const auto key = static_cast<std::uint32_t>(bin << kDroppedBits);
  const std::uint32_t bits = (key & kSignBit) ? key & ~kSignBit : ~key;
  return std::bit_cast<float>(bits & ~kDroppedMask);
}

/// Index of the bin holding the sample of rank percent/100 * (count - 1).
std::size_t binOfPercentile(const std::vector<std::uint64_t>& bins, std::int64_t count, double percent) {
  const double rank = std::clamp(percent, 0.0, 100.0) / 100.0 * static_cast<double>(count - 1);
  std::uint64_t below = 0;
  for (std::size_t b = 0; b < bins.size(); ++b) {
    below += bins[b];
    if (static_cast<double>(below) > rank) return b;
  }
  return bins.size() - 1;
}

}  // namespace

SampleStatistics::SampleStatistics(double clip)
    : signedBins_(std::size_t{1} << (32 - kDroppedBits)), absBins_(std::size_t{1} << (31 - kDroppedBits)) {
  summary_.clip = clip;
}

void SampleStatistics::add(const float* values, std::size_t count) {
  const auto clip = static_cast<float>(summary_.clip);
  for (std::size_t i = 0; i < count; ++i) {
    const float v = values[i];
    if (std::isnan(v)) {
      ++summary_.holes;
      continue;
    }
    if (summary_.samples == 0) summary_.minValue = summary_.maxValue = v;
    summary_.minValue = std::min(summary_.minValue, v);
    summary_.maxValue = std::max(summary_.maxValue, v);
    ++summary_.samples;
    if (!(std::abs(v) < clip)) ++summary_.activeSamples;
    ++signedBins_[orderedKey(v) >> kDroppedBits];
    ++absBins_[(std::bit_cast<std::uint32_t>(v) & ~kSignBit) >> kDroppedBits];
  }
}

float SampleStatistics::percentile(double percent) const {
  if (summary_.samples == 0) return 0.f;
  const float value = valueOfOrderedBin(binOfPercentile(signedBins_, summary_.samples, percent));
  return std::clamp(value, summary_.minValue, summary_.maxValue);
}

float SampleStatistics::absPercentile(double percent) const {
  if (summary_.samples == 0) return 0.f;
  const std::size_t bin = binOfPercentile(absBins_, summary_.samples, percent);
  const float value = std::bit_cast<float>(static_cast<std::uint32_t>(bin << kDroppedBits));
  return std::clamp(value, 0.f, std::max(std::abs(summary_.minValue), std::abs(summary_.maxValue)));
}

void ObservedSliceStream::readSlice(float* out) {
  inner_.readSlice(out);
  statistics_.add(out, static_cast<std::size_t>(inner_.header().sliceSamples()));
}

}  // namespace isovdb::io
