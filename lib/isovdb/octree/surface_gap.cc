// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/surface_gap.h"

#include <algorithm>
#include <cmath>

namespace isovdb::octree {

float surfaceGap(const cell::MetaCellSamples& samples, std::array<int, 3> origin, int size,
                 const std::array<float, 3>& x, float iso) noexcept {
  // The cell's samples and kGapMargin beyond (within the block): a vertex on the cell's
  // boundary needs samples past it to be seen off the surface.
  std::array<int, 3> lo{}, hi{};
  for (std::size_t a = 0; a < 3; ++a) {
    lo[a] = std::max(origin[a] - kGapMargin, -samples.apron);
    hi[a] = std::min(origin[a] + size + kGapMargin, samples.size + samples.apron);
  }
  float gap = 0.0f;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j) {
      const float dy = static_cast<float>(j) - x[1], dz = static_cast<float>(k) - x[2];
      const float* row = samples.values.data() + samples.indexOf(lo[0], j, k);
      for (int i = 0; i <= hi[0] - lo[0]; ++i) {
        const float d = std::abs(row[i] - iso);
        if (d <= gap) continue;  // cannot raise the bound: |s - x| >= 0
        const float dx = static_cast<float>(lo[0] + i) - x[0];
        gap = std::max(gap, d - std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
  return gap;
}

}  // namespace isovdb::octree
