// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/surface_deviation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "isovdb/cell/trilinear.h"

namespace isovdb::octree {

namespace {

/// Calls `visit(start, axis)` for every bipolar unit edge of the closed cell, reading
/// the phase bits a row of x (up to 64 samples) at a time.
template <class Visit>
void forEachBipolarUnitEdge(const SamplePhases& phases, std::array<int, 3> origin, int size, Visit&& visit) {
  const auto visitBits = [&](std::uint64_t bits, int i0, int j, int k, int axis) {
    while (bits != 0) {
      const int t = std::countr_zero(bits);
      bits &= bits - 1;
      visit(std::array<int, 3>{origin[0] + i0 + t, origin[1] + j, origin[2] + k}, axis);
    }
  };
  const auto at = [&](int i, int j, int k, int length) {
    return phases.row(origin[0] + i, origin[1] + j, origin[2] + k, length);
  };
  for (int k = 0; k <= size; ++k)
    for (int j = 0; j <= size; ++j) {
      // Along x: 63 edges from 64 samples per word.
      for (int i0 = 0; i0 < size; i0 += 63) {
        const int edges = std::min(63, size - i0);
        const std::uint64_t bits = at(i0, j, k, edges + 1);
        visitBits((bits ^ (bits >> 1)) & SamplePhases::lowBits(edges), i0, j, k, 0);
      }
      // Along y and z: a row against the next row or slice.
      for (int i0 = 0; i0 <= size; i0 += 64) {
        const int length = std::min(64, size + 1 - i0);
        const std::uint64_t bits = at(i0, j, k, length);
        if (j < size) visitBits(bits ^ at(i0, j + 1, k, length), i0, j, k, 1);
        if (k < size) visitBits(bits ^ at(i0, j, k + 1, length), i0, j, k, 2);
      }
    }
}

}  // namespace

float surfaceDeviation(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                       int size, const Vec3f& vertex, float iso) {
  thread_local std::vector<Vec3f> points;
  points.clear();
  std::array<double, 3> normal{0.0, 0.0, 0.0};
  forEachBipolarUnitEdge(phases, origin, size, [&](std::array<int, 3> start, int axis) {
    std::array<int, 3> end = start;
    ++end[axis];
    const float a = samples.value(start) - iso;
    const float b = samples.value(end) - iso;
    Vec3f p{static_cast<float>(start[0]), static_cast<float>(start[1]), static_cast<float>(start[2])};
    p[axis] += a / (a - b);  // a <= 0 < b or b <= 0 < a: a != b
    points.push_back(p);
    normal[axis] += b > a ? 1.0 : -1.0;  // the field rises outward
  });
  if (points.empty()) return 0.0f;
  // The field's own normal at the vertex where it has one: the signs' sum is coarse in a
  // cell crossed by a handful of unit edges.
  const cell::TrilinearSample f = cell::trilinearAt(samples, vertex, iso);
  if (f.gradient != Vec3f{0.0f, 0.0f, 0.0f})
    for (int a = 0; a < 3; ++a) normal[a] = f.gradient[a];
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if (length == 0.0) return std::numeric_limits<float>::infinity();
  double deviation = 0.0;
  for (const Vec3f& p : points) {
    double d = 0.0;
    for (int a = 0; a < 3; ++a) d += normal[a] * (static_cast<double>(p[a]) - vertex[a]);
    deviation = std::max(deviation, std::abs(d));
  }
  return static_cast<float>(deviation / length);
}

}  // namespace isovdb::octree
