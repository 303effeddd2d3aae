// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file split_mix.h
/// @brief splitmix64: a tiny seedable generator whose stream, and the doubles made
///        from it, are the same on every platform and standard library (unlike
///        std::uniform_real_distribution): particle seeding (morph) and the
///        random sample shapes (data/generators) depend on it for reproducibility.
#pragma once

#include <cstdint>

namespace isovdb {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

}  // namespace isovdb
