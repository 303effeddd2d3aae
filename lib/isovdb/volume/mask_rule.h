// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mask_rule.h
/// @brief Which samples of a dense volume are inside the object.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace isovdb::volume {

/// How MaskRule compares a sample with its bounds.
enum class MaskTest {
  Above,    ///< inside iff value > threshold (binary and grey volumes; `--threshold`, `--mask "above A"`)
  Below,    ///< inside iff value < threshold (`--mask "below A"`: seismic troughs)
  Between,  ///< inside iff threshold <= value <= upper (`--mask-range lo,hi`)
};

/// Inside test of a sample: a comparison (`test`), or membership in `labels`
/// (label volumes) when labels is not empty. NaN samples (holes) are never inside.
struct MaskRule {
  MaskTest test = MaskTest::Above;
  double threshold = 0.0;      ///< bound of Above/Below, lower bound of Between
  double upper = 0.0;          ///< upper bound of Between (inclusive)
  std::vector<double> labels;  ///< label volumes: inside iff value is one of these

  bool inside(float value) const {
    if (!labels.empty()) return std::find(labels.begin(), labels.end(), static_cast<double>(value)) != labels.end();
    switch (test) {
      case MaskTest::Above:
        return value > threshold;
      case MaskTest::Below:
        return value < threshold;
      case MaskTest::Between:
        return value >= threshold && value <= upper;
    }
    return false;
  }
  /// inside() of every value, as 1 or 0 in `out` (values.size() bytes). The rule is
  /// chosen once and each comparison is a plain loop the compiler vectorises: inside()
  /// value by value was half of reading a 1 GiB mask.
  void classify(std::span<const float> values, std::uint8_t* out) const;
  /// "value > 0", "value < -3000", "value in [1000, 2000]" or "label in {13}" —
  /// for messages and statistics.
  std::string describe() const;
};

/// Parses `--mask` text: "above A" or "below A" (A a number).
/// @throw InputError "--mask: expected 'above A' or 'below A', got '...'".
MaskRule parseMaskText(const std::string& text);

}  // namespace isovdb::volume
