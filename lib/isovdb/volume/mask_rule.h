/// @file mask_rule.h
/// @brief Which samples of a dense volume are inside the object.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace isovdb::volume {

/// Inside = value > threshold (binary or grey volumes), or value equal to one of
/// `labels` (label volumes) when labels is not empty.
struct MaskRule {
  double threshold = 0.0;      ///< used when `labels` is empty: inside iff value > threshold
  std::vector<double> labels;  ///< label volumes: inside iff value is one of these

  bool inside(float value) const {
    if (labels.empty()) return value > threshold;
    return std::find(labels.begin(), labels.end(), static_cast<double>(value)) != labels.end();
  }
  /// "value > 0" or "label in {13}" — for messages and statistics.
  std::string describe() const;
};

}  // namespace isovdb::volume
