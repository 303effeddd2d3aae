// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/edge_intersection.h"

#include <cstddef>

#include "isovdb/cell/crease_crossing.h"

namespace isovdb::cell {

bool intersectEdge(const cell::MetaCellSamples& samples, std::array<int, 3> start, int axis, int length, float iso,
                   EdgeIntersection& out, bool sharpFeatures) noexcept {
  const std::ptrdiff_t step = samples.axisStep(axis);
  const float* p = samples.values.data() + samples.indexOf(start[0], start[1], start[2]);
  bool prev = cell::isInside(p[0], iso);
  int first = -1, transitions = 0;
  for (int t = 1; t <= length; ++t) {
    const bool cur = cell::isInside(p[t * step], iso);
    if (cur != prev) {
      if (first < 0) first = t - 1;
      ++transitions;
    }
    prev = cur;
  }
  if (first < 0) return false;
  const float t = crossingFraction(p[first * step], p[(first + 1) * step], iso);
  std::array<int, 3> s0 = start;
  s0[axis] += first;
  out.point = {static_cast<float>(s0[0]), static_cast<float>(s0[1]), static_cast<float>(s0[2])};
  out.point[axis] += t;
  CreaseCrossing crease;
  if (sharpFeatures && crossingBesideCrease(samples, s0, axis, t, iso, crease)) {
    out.point[axis] = static_cast<float>(s0[axis]) + crease.t;
    out.normal = normalized(crease.gradient);
  } else {
    out.normal = normalized(prewittGradientOnEdge(samples, s0, axis, t));
  }
  out.transitions = transitions;
  return true;
}

EdgeIntersection unitEdgeCrossing(const cell::MetaCellSamples& samples, const std::array<int, 3>& start, int axis,
                                  float iso, const Vec3f& g0, const Vec3f& g1) noexcept {
  const std::ptrdiff_t step = samples.axisStep(axis);
  const float* p = samples.values.data() + samples.indexOf(start[0], start[1], start[2]);
  const float t = crossingFraction(p[0], p[step], iso);
  EdgeIntersection out;
  out.point = {static_cast<float>(start[0]), static_cast<float>(start[1]), static_cast<float>(start[2])};
  out.point[static_cast<std::size_t>(axis)] += t;
  out.normal = normalized(gradientBetween(g0, g1, t));
  out.transitions = 1;
  return out;
}

}  // namespace isovdb::cell
