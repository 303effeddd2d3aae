// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/gradient.h"

#include <cmath>
#include <cstddef>

namespace isovdb::cell {

Vec3f prewittGradient(const cell::MetaCellSamples& samples, int i, int j, int k) noexcept {
  const std::ptrdiff_t sx = 1, sy = samples.stride(), sz = static_cast<std::ptrdiff_t>(sy) * sy;
  const float* c = samples.values.data() + samples.indexOf(i, j, k);
  float gx = 0.0f, gy = 0.0f, gz = 0.0f;
  for (int b = -1; b <= 1; ++b)
    for (int a = -1; a <= 1; ++a) {
      const float* px = c + a * sy + b * sz;  // (y, z) neighbourhood for d/dx
      gx += px[sx] - px[-sx];
      const float* py = c + a * sx + b * sz;  // (x, z) neighbourhood for d/dy
      gy += py[sy] - py[-sy];
      const float* pz = c + a * sx + b * sy;  // (x, y) neighbourhood for d/dz
      gz += pz[sz] - pz[-sz];
    }
  constexpr float kScale = 1.0f / 18.0f;  // 9 differences over 2 voxels each
  return {gx * kScale, gy * kScale, gz * kScale};
}

Vec3f prewittGradientOnEdge(const cell::MetaCellSamples& samples, std::array<int, 3> sample0, int axis,
                            float t) noexcept {
  std::array<int, 3> sample1 = sample0;
  ++sample1[axis];
  const Vec3f g0 = prewittGradient(samples, sample0[0], sample0[1], sample0[2]);
  if (t <= 0.0f) return g0;
  const Vec3f g1 = prewittGradient(samples, sample1[0], sample1[1], sample1[2]);
  return {g0[0] + t * (g1[0] - g0[0]), g0[1] + t * (g1[1] - g0[1]), g0[2] + t * (g1[2] - g0[2])};
}

Vec3f normalized(const Vec3f& v) noexcept {
  const float len = std::sqrt(dot(v, v));
  if (!(len > 0.0f) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f};
  return {v[0] / len, v[1] / len, v[2] / len};
}

}  // namespace isovdb::cell
