// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/trilinear.h"

#include <algorithm>
#include <array>
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
  // The cell's eight samples (f<x><y><z>), then the value and the gradient as nested lerps.
  const std::size_t sy = static_cast<std::size_t>(samples.stride()), sz = sy * sy;
  const float* v = samples.values.data() + samples.indexOf(base[0], base[1], base[2]);
  const float f000 = v[0] - iso, f100 = v[1] - iso, f010 = v[sy] - iso, f110 = v[sy + 1] - iso;
  const float f001 = v[sz] - iso, f101 = v[sz + 1] - iso, f011 = v[sz + sy] - iso, f111 = v[sz + sy + 1] - iso;
  const float tx = t[0], ty = t[1], tz = t[2], ux = 1.0f - tx, uy = 1.0f - ty, uz = 1.0f - tz;
  const float x00 = f000 * ux + f100 * tx, x10 = f010 * ux + f110 * tx;  // along x, at (y, z)
  const float x01 = f001 * ux + f101 * tx, x11 = f011 * ux + f111 * tx;
  TrilinearSample result;
  result.value = (x00 * uy + x10 * ty) * uz + (x01 * uy + x11 * ty) * tz;
  result.gradient[0] = ((f100 - f000) * uy + (f110 - f010) * ty) * uz + ((f101 - f001) * uy + (f111 - f011) * ty) * tz;
  result.gradient[1] = (x10 - x00) * uz + (x11 - x01) * tz;
  result.gradient[2] = (x01 * uy + x11 * ty) - (x00 * uy + x10 * ty);
  return result;
}

float distanceToLevel(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept {
  const TrilinearSample f = trilinearAt(samples, point, iso);
  if (f.value == 0.0f) return 0.0f;
  const Vec3f& g = f.gradient;
  const float length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  return length > 0.0f ? std::abs(f.value) / length : std::numeric_limits<float>::infinity();
}

bool levelWithin(const MetaCellSamples& samples, const Vec3f& point, float iso, float radius) noexcept {
  // A point that is not finite has no cell to interpolate in (trilinearAt would convert NaN).
  if (!(radius >= 0.0f) || !std::isfinite(point[0] + point[1] + point[2])) return false;
  if (distanceToLevel(samples, point, iso) <= radius) return true;
  const int lo = -samples.apron, hi = samples.size + samples.apron;
  std::array<int, 3> from{}, to{};
  for (int a = 0; a < 3; ++a) {  // clamped as floats: a huge radius must not overflow an int
    from[a] =
        static_cast<int>(std::clamp(std::floor(point[a] - radius), static_cast<float>(lo), static_cast<float>(hi)));
    to[a] = static_cast<int>(std::clamp(std::floor(point[a] + radius), static_cast<float>(lo), static_cast<float>(hi)));
  }
  const float limit = radius * radius;
  for (int k = from[2]; k <= to[2]; ++k)
    for (int j = from[1]; j <= to[1]; ++j)
      for (int i = from[0]; i <= to[0]; ++i) {
        const bool inside = isInside(samples.value(i, j, k), iso);
        for (int axis = 0; axis < 3; ++axis) {
          std::array<int, 3> end{i, j, k};
          if (++end[axis] > hi || isInside(samples.value(end[0], end[1], end[2]), iso) == inside) continue;
          const Vec3f c = unitEdgeCrossing(samples, {i, j, k}, axis, iso).point;
          float d = 0.0f;
          for (int n = 0; n < 3; ++n) d += (c[n] - point[n]) * (c[n] - point[n]);
          if (d <= limit) return true;
        }
      }
  return false;
}

}  // namespace isovdb::cell
