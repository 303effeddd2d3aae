// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/gradient.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace isovdb::cell {

namespace {

/// The stencil itself, on the values as they are.
Vec3f prewittOfValues(const cell::MetaCellSamples& samples, int i, int j, int k) noexcept {
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

}  // namespace

Vec3f prewittGradient(const cell::MetaCellSamples& samples, int i, int j, int k) noexcept {
  if (samples.boxRim.active)
    if (const Vec3f* kept = samples.boxRim.find(i, j, k)) return *kept;
  return prewittOfValues(samples, i, j, k);
}

void keepBoxRimGradients(cell::MetaCellSamples& samples, const std::array<int, 3>& boxMin,
                         const std::array<int, 3>& boxMax) {
  BoxRimGradients& rim = samples.boxRim;
  rim.active = false;
  rim.stride = samples.stride();
  rim.apron = samples.apron;
  // Stencils fit the block at offsets [lo, hi].
  const int lo = 1 - samples.apron, hi = samples.size + samples.apron - 1;
  for (std::size_t a = 0; a < 3; ++a) {
    rim.first[a] = boxMin[a] - samples.origin[a];
    rim.last[a] = boxMax[a] - samples.origin[a];
  }
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const auto f = static_cast<std::size_t>(2 * a + side);
      const int plane = (side ? rim.last : rim.first)[static_cast<std::size_t>(a)];
      // Kept where a stencil on the face reads the block's samples beyond it.
      rim.kept[f] = plane >= lo && plane <= hi;
      if (!rim.kept[f]) continue;
      rim.faces[f].assign(static_cast<std::size_t>(rim.stride) * static_cast<std::size_t>(rim.stride),
                          Vec3f{0.0f, 0.0f, 0.0f});
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      const auto range = [&](int axis) {
        const auto b = static_cast<std::size_t>(axis);
        return std::array<int, 2>{std::max(lo, rim.first[b]), std::min(hi, rim.last[b])};
      };
      const std::array<int, 2> ru = range(u), rv = range(v);
      for (int pv = rv[0]; pv <= rv[1]; ++pv)
        for (int pu = ru[0]; pu <= ru[1]; ++pu) {
          std::array<int, 3> p{};
          p[static_cast<std::size_t>(a)] = plane;
          p[static_cast<std::size_t>(u)] = pu;
          p[static_cast<std::size_t>(v)] = pv;
          rim.faces[f][rim.slot(p, a)] = prewittOfValues(samples, p[0], p[1], p[2]);
        }
    }
  rim.active = std::any_of(rim.kept.begin(), rim.kept.end(), [](bool k) { return k; });
}

Vec3f prewittGradientOnEdge(const cell::MetaCellSamples& samples, std::array<int, 3> sample0, int axis,
                            float t) noexcept {
  std::array<int, 3> sample1 = sample0;
  ++sample1[axis];
  const Vec3f g0 = prewittGradient(samples, sample0[0], sample0[1], sample0[2]);
  if (t <= 0.0f) return g0;
  return gradientBetween(g0, prewittGradient(samples, sample1[0], sample1[1], sample1[2]), t);
}

Vec3f normalized(const Vec3f& v) noexcept {
  const float len = std::sqrt(dot(v, v));
  if (!(len > 0.0f) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f};
  return {v[0] / len, v[1] / len, v[2] / len};
}

}  // namespace isovdb::cell
