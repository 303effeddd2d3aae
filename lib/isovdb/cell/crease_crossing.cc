// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/crease_crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isovdb::cell {
namespace {

/// A voxel plane "fits" within this (voxels): RMS residual on its corners and error at the
/// crossing. An exact distance field fits a face to rounding; a curved face of radius r
/// misses by about 0.1 / r over a voxel (0.008 on the test cylinder's r = 14.3).
constexpr float kFit = 0.05f;
/// Voxels whose gradients are closer than this (cosine, about 25 degrees) see the same face.
constexpr float kSameFace = 0.9f;

/// Least-squares plane through the 8 corners of one unit voxel.
struct VoxelPlane {
  Vec3f gradient{0.0f, 0.0f, 0.0f};
  Vec3f centre{0.0f, 0.0f, 0.0f};
  float mean = 0.0f;      ///< plane value at the centre
  float residual = 0.0f;  ///< RMS of the corners off the plane

  float at(const Vec3f& x) const noexcept {
    return mean + gradient[0] * (x[0] - centre[0]) + gradient[1] * (x[1] - centre[1]) +
           gradient[2] * (x[2] - centre[2]);
  }
};

VoxelPlane fitVoxel(const cell::MetaCellSamples& samples, const std::array<int, 3>& minCorner) noexcept {
  std::array<float, 8> c{};
  VoxelPlane plane;
  for (std::size_t i = 0; i < 8; ++i) {
    c[i] = samples.value(minCorner[0] + static_cast<int>(i & 1), minCorner[1] + static_cast<int>((i >> 1) & 1),
                         minCorner[2] + static_cast<int>((i >> 2) & 1));
    plane.mean += c[i];
  }
  plane.mean *= 0.125f;
  for (std::size_t a = 0; a < 3; ++a) {  // mean of the voxel's 4 differences along a
    float sum = 0.0f;
    for (std::size_t i = 0; i < 8; ++i)
      if ((i >> a) & 1) sum += c[i] - c[i ^ (std::size_t{1} << a)];
    plane.gradient[a] = 0.25f * sum;
    plane.centre[a] = static_cast<float>(minCorner[a]) + 0.5f;
  }
  float r2 = 0.0f;
  for (std::size_t i = 0; i < 8; ++i) {  // corners at +-0.5 from the centre
    float r = c[i] - plane.mean;
    for (std::size_t a = 0; a < 3; ++a) r -= plane.gradient[a] * (((i >> a) & 1) ? 0.5f : -0.5f);
    r2 += r * r;
  }
  plane.residual = std::sqrt(r2 * 0.125f);
  return plane;
}

Vec3f toFloat(const std::array<int, 3>& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

}  // namespace

bool crossingBesideCrease(const cell::MetaCellSamples& samples, std::array<int, 3> sample0, int axis, float t,
                          float iso, CreaseCrossing& out) noexcept {
  const auto ax = static_cast<std::size_t>(axis);
  std::array<int, 3> sample1 = sample0;
  ++sample1[ax];
  const Vec3f p0 = toFloat(sample0), p1 = toFloat(sample1);
  const float f0 = samples.value(sample0), f1 = samples.value(sample1);
  Vec3f linear = p0;
  linear[ax] += t;
  const std::array<std::size_t, 2> uv{static_cast<std::size_t>((axis + 1) % 3),
                                      static_cast<std::size_t>((axis + 2) % 3)};
  constexpr float kNoFit = std::numeric_limits<float>::infinity();
  std::array<VoxelPlane, 12> planes;
  std::array<float, 12> tOf{}, score{};
  std::size_t n = 0;
  bool allFit = true;
  for (int along = -1; along <= 1; ++along)
    for (int du = -1; du <= 0; ++du)
      for (int dv = -1; dv <= 0; ++dv, ++n) {
        std::array<int, 3> m = sample0;
        m[ax] += along;
        m[uv[0]] += du;
        m[uv[1]] += dv;
        const VoxelPlane& plane = planes[n] = fitVoxel(samples, m);
        allFit = allFit && std::hypot(plane.residual, plane.at(linear) - iso) <= kFit;
        // A face the crossing may lie on: the plane meets the edge between its samples
        // and predicts the end sample on its side (the other may read the other face).
        const float g = plane.gradient[ax];
        tOf[n] = std::abs(g) > 1e-6f ? (iso - plane.at(p0)) / g : -1.0f;
        score[n] = tOf[n] >= -kFit && tOf[n] <= 1.0f + kFit
                       ? plane.residual + std::min(std::abs(plane.at(p0) - f0), std::abs(plane.at(p1) - f1))
                       : kNoFit;
      }
  if (allFit) return false;  // smooth here: linear interpolation and Prewitt are right
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (score[i] < score[best]) best = i;
  if (!(score[best] <= kFit)) return false;
  // The voxels that see the best one's face (similar fit, similar gradient) vote.
  const Vec3f bestDirection = normalized(planes[best].gradient);
  Vec3f sum{0.0f, 0.0f, 0.0f};
  float tSum = 0.0f;
  int votes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(score[i] <= score[best] + kFit) || dot(normalized(planes[i].gradient), bestDirection) < kSameFace) continue;
    for (std::size_t a = 0; a < 3; ++a) sum[a] += planes[i].gradient[a];
    tSum += tOf[i];
    ++votes;
  }
  out.t = std::clamp(tSum / static_cast<float>(votes), 0.0f, 1.0f);
  out.gradient = sum;
  return true;
}

}  // namespace isovdb::cell
