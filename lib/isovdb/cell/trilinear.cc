// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/trilinear.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isovdb::cell {

TrilinearSample trilinearAt(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept {
  std::array<int, 3> base{};
  std::array<float, 3> t{};
  for (int a = 0; a < 3; ++a) {
    base[a] = std::clamp(static_cast<int>(std::floor(point[a])), 0, samples.size - 1);
    t[a] = point[a] - static_cast<float>(base[a]);
  }
  TrilinearSample result;
  for (int c = 0; c < 8; ++c) {
    const std::array<int, 3> bit{c & 1, (c >> 1) & 1, (c >> 2) & 1};
    const float f = samples.value(base[0] + bit[0], base[1] + bit[1], base[2] + bit[2]) - iso;
    std::array<float, 3> w{};
    for (int a = 0; a < 3; ++a) w[a] = bit[a] ? t[a] : 1.0f - t[a];
    result.value += f * w[0] * w[1] * w[2];
    for (int a = 0; a < 3; ++a) result.gradient[a] += f * (bit[a] ? 1.0f : -1.0f) * w[(a + 1) % 3] * w[(a + 2) % 3];
  }
  return result;
}

float distanceToLevel(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept {
  const TrilinearSample f = trilinearAt(samples, point, iso);
  if (f.value == 0.0f) return 0.0f;
  const Vec3f& g = f.gradient;
  const float length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  return length > 0.0f ? std::abs(f.value) / length : std::numeric_limits<float>::infinity();
}

}  // namespace isovdb::cell
