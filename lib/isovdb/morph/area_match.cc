// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/area_match.h"

#include <algorithm>
#include <vector>

namespace isovdb::morph {

double shiftToArea(Field2& phi, std::int64_t area) {
  if (phi.size() == 0 || area >= static_cast<std::int64_t>(phi.size())) return 0;
  if (area <= 0) {  // nothing inside: the smallest value goes to +0.5
    const double lowest = *std::min_element(phi.values.begin(), phi.values.end());
    if (lowest > 0) return 0;
    const double shift = lowest - 0.5;
    for (float& v : phi.values) v = static_cast<float>(v - shift);
    return shift;
  }
  std::vector<float> sorted = phi.values;
  // The area-th smallest value is the last one kept inside, the next one the first outside.
  const auto outside = sorted.begin() + area;
  std::nth_element(sorted.begin(), outside, sorted.end());
  const float firstOutside = *outside;
  const float lastInside = *std::max_element(sorted.begin(), outside);
  const double shift = 0.5 * (double(lastInside) + double(firstOutside));
  for (float& v : phi.values) v = static_cast<float>(v - shift);
  return shift;
}

}  // namespace isovdb::morph
