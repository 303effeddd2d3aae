// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/trilinear.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "isovdb/cell/dmc_table.h"
#include "isovdb/cell/dual_vertex.h"

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

namespace {

/// True if the level `iso` crosses the cell trilinearAt interpolates `point` in (some corner
/// inside, some outside).
bool cellCrossed(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept {
  std::array<int, 3> base{};
  for (int a = 0; a < 3; ++a) base[a] = std::clamp(static_cast<int>(std::floor(point[a])), 0, samples.size - 1);
  const std::uint8_t signs = cellCornerSigns(samples, base, 1, iso);
  return signs != 0 && signs != 0xff;
}

}  // namespace

bool levelWithin(const MetaCellSamples& samples, const Vec3f& point, const DualVertexOptions& options,
                 float radius) noexcept {
  // A point that is not finite has no cell to interpolate in (trilinearAt would convert NaN).
  if (!(radius >= 0.0f) || !std::isfinite(point[0] + point[1] + point[2])) return false;
  // The first-order distance extrapolates the field: it is trusted only inside a cell the level
  // crosses. Beside one-voxel gaps between bodies it read 0.8 voxel where regular mode's mesh
  // was 1.2 away.
  if (distanceToLevel(samples, point, options.iso) <= radius && cellCrossed(samples, point, options.iso)) return true;
  // The meta-cell's unit cells whose box comes within the radius (a vertex lies in its cell;
  // the cells' Prewitt normals read one sample beyond them, which the apron holds).
  std::array<int, 3> from{}, to{};
  for (int a = 0; a < 3; ++a) {  // clamped as floats: a huge radius must not overflow an int
    const auto last = static_cast<float>(samples.size - 1);
    from[a] = static_cast<int>(std::clamp(std::floor(point[a] - radius) - 1.0f, 0.0f, last));
    to[a] = static_cast<int>(std::clamp(std::floor(point[a] + radius), 0.0f, last));
  }
  const float limit = radius * radius;
  const auto squaredDistanceTo = [&point](const std::array<float, 3>& lo, const std::array<float, 3>& hi) {
    float d = 0.0f;
    for (int n = 0; n < 3; ++n) {
      const float gap = std::max({lo[n] - point[n], 0.0f, point[n] - hi[n]});
      d += gap * gap;
    }
    return d;
  };
  DualVertexOptions vertexOptions = options;
  vertexOptions.positionOnly = true;
  for (int k = from[2]; k <= to[2]; ++k)
    for (int j = from[1]; j <= to[1]; ++j)
      for (int i = from[0]; i <= to[0]; ++i) {
        const std::array<float, 3> lo{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
        if (squaredDistanceTo(lo, {lo[0] + 1.0f, lo[1] + 1.0f, lo[2] + 1.0f}) > limit) continue;
        const DmcEntry& entry = dmcEntry(cellCornerSigns(samples, {i, j, k}, 1, options.iso));
        vertexOptions.massPointOnly = entry.vertexCount > 1;
        for (int g = 0; g < entry.vertexCount; ++g) {
          const DualVertex v =
              computeDualVertex(samples, {i, j, k}, 1, entry.groups[static_cast<std::size_t>(g)], vertexOptions);
          if (!v.valid()) continue;
          const std::array<float, 3> at{v.position[0] - static_cast<float>(samples.origin[0]),
                                        v.position[1] - static_cast<float>(samples.origin[1]),
                                        v.position[2] - static_cast<float>(samples.origin[2])};
          if (squaredDistanceTo(at, at) <= limit) return true;
        }
      }
  return false;
}

}  // namespace isovdb::cell
