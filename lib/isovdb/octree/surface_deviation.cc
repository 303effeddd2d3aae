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
/// the phase bits a row of x (up to 64 samples) at a time, until `visit` returns false.
/// Returns false if it was stopped.
template <class Visit>
bool forEachBipolarUnitEdge(const SamplePhases& phases, std::array<int, 3> origin, int size, Visit&& visit) {
  const auto visitBits = [&](std::uint64_t bits, int i0, int j, int k, int axis) {
    while (bits != 0) {
      const int t = std::countr_zero(bits);
      bits &= bits - 1;
      if (!visit(std::array<int, 3>{origin[0] + i0 + t, origin[1] + j, origin[2] + k}, axis)) return false;
    }
    return true;
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
        if (!visitBits((bits ^ (bits >> 1)) & SamplePhases::lowBits(edges), i0, j, k, 0)) return false;
      }
      // Along y and z: a row against the next row or slice.
      for (int i0 = 0; i0 <= size; i0 += 64) {
        const int length = std::min(64, size + 1 - i0);
        const std::uint64_t bits = at(i0, j, k, length);
        if (j < size && !visitBits(bits ^ at(i0, j + 1, k, length), i0, j, k, 1)) return false;
        if (k < size && !visitBits(bits ^ at(i0, j, k + 1, length), i0, j, k, 2)) return false;
      }
    }
  return true;
}

/// The crossing on a bipolar unit edge (linear interpolation), and whether the field
/// rises along the edge's axis there.
struct UnitCrossing {
  Vec3f point;
  bool rises;
};

[[gnu::always_inline]] inline UnitCrossing unitEdgeCrossing(const cell::MetaCellSamples& samples,
                                                            std::array<int, 3> start, int axis, float iso) {
  std::array<int, 3> end = start;
  ++end[static_cast<std::size_t>(axis)];
  const float a = samples.value(start) - iso;
  const float b = samples.value(end) - iso;
  Vec3f p{static_cast<float>(start[0]), static_cast<float>(start[1]), static_cast<float>(start[2])};
  p[static_cast<std::size_t>(axis)] += a / (a - b);  // a <= 0 < b or b <= 0 < a: a != b
  return {p, b > a};
}

double planeDistance(const std::array<double, 3>& normal, const Vec3f& p, const Vec3f& vertex) {
  double d = 0.0;
  for (int a = 0; a < 3; ++a) d += normal[a] * (static_cast<double>(p[a]) - vertex[a]);
  return std::abs(d);
}

/// surfaceDeviation, stopped as soon as it exceeds `stopAbove` (then some value above it).
float deviationUpTo(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                    int size, const Vec3f& vertex, float iso, float stopAbove) {
  const cell::TrilinearSample f = cell::trilinearAt(samples, vertex, iso);
  if (f.gradient != Vec3f{0.0f, 0.0f, 0.0f}) {
    // The field's own normal at the vertex: each crossing is measured as it is found.
    const std::array<double, 3> normal{f.gradient[0], f.gradient[1], f.gradient[2]};
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    double deviation = 0.0;
    forEachBipolarUnitEdge(phases, origin, size, [&](std::array<int, 3> start, int axis) {
      deviation = std::max(deviation, planeDistance(normal, unitEdgeCrossing(samples, start, axis, iso).point, vertex));
      return !(static_cast<float>(deviation / length) > stopAbove);
    });
    return static_cast<float>(deviation / length);
  }
  // Where the gradient vanishes, the crossings' own normals (the signs' sum) are needed
  // before any distance.
  thread_local std::vector<Vec3f> points;
  points.clear();
  std::array<double, 3> normal{0.0, 0.0, 0.0};
  forEachBipolarUnitEdge(phases, origin, size, [&](std::array<int, 3> start, int axis) {
    const UnitCrossing c = unitEdgeCrossing(samples, start, axis, iso);
    points.push_back(c.point);
    normal[axis] += c.rises ? 1.0 : -1.0;  // the field rises outward
    return true;
  });
  if (points.empty()) return 0.0f;
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if (length == 0.0) return std::numeric_limits<float>::infinity();
  double deviation = 0.0;
  for (const Vec3f& p : points) deviation = std::max(deviation, planeDistance(normal, p, vertex));
  return static_cast<float>(deviation / length);
}

}  // namespace

float surfaceDeviation(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                       int size, const Vec3f& vertex, float iso) {
  return deviationUpTo(samples, phases, origin, size, vertex, iso, std::numeric_limits<float>::infinity());
}

bool surfaceDeviatesBeyond(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                           int size, const Vec3f& vertex, float iso, float allowed) {
  return deviationUpTo(samples, phases, origin, size, vertex, iso, allowed) > allowed;
}

}  // namespace isovdb::octree
