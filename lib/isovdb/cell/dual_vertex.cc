// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/dual_vertex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "isovdb/cell/edge_intersection.h"
#include "isovdb/cell/gradient.h"
#include "isovdb/cell/cell_geometry.h"

namespace isovdb::cell {

float DualVertex::rmsError() const noexcept {
  return intersections > 0 ? std::sqrt(std::max(qefError, 0.0f) / static_cast<float>(intersections)) : 0.0f;
}

namespace {

/// The point of the line x + t d (the QEF's minimisers on a crease) in the cell box nearest
/// x, or x if the line misses the box: a crease that crosses the cell near a corner has its
/// minimiser nearest the mass point just outside, while the cell holds a part of it.
Vec3f slideIntoCell(const Vec3f& x, const Vec3f& d, std::array<int, 3> cellOrigin, int cellSize) {
  float lo = -std::numeric_limits<float>::infinity(), hi = std::numeric_limits<float>::infinity();
  for (std::size_t a = 0; a < 3; ++a) {
    const float boxLo = static_cast<float>(cellOrigin[a]), boxHi = static_cast<float>(cellOrigin[a] + cellSize);
    if (std::abs(d[a]) < 1e-6f) {
      if (x[a] < boxLo || x[a] > boxHi) return x;
      continue;
    }
    float t0 = (boxLo - x[a]) / d[a], t1 = (boxHi - x[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  if (lo > hi) return x;
  const float t = std::clamp(0.0f, lo, hi);
  return {x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]};
}

}  // namespace

DualVertex computeDualVertex(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                             std::uint16_t edgeMask, const DualVertexOptions& options) {
  EdgeIntersection hit;
  return dualVertexOfCrossings(
      samples, cellOrigin, cellSize, edgeMask, options,
      [&](const std::array<int, 3>& start, int axis) -> const EdgeIntersection* {
        std::array<int, 3> end = start;
        end[static_cast<std::size_t>(axis)] += cellSize;
        if (isInside(samples.value(start), options.iso) == isInside(samples.value(end), options.iso))
          return nullptr;  // not bipolar
        const bool found = intersectEdge(samples, start, axis, cellSize, options.iso, hit, options.sharpFeatures);
        return found ? &hit : nullptr;
      });
}

DualVertex dualVertexFromCrossings(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                                   std::span<const Vec3f> points, std::span<const Vec3f> normals, std::uint16_t edges,
                                   const DualVertexOptions& options) {
  DualVertex v;
  const std::size_t n = points.size();
  if (n == 0) return v;
  v.edges = edges;
  // (With sharp features a rank-2 minimiser slides along its free direction.)
  const QefSolution s = solveQef(points, normals,
                                 QefOptions{.singularValueThreshold = options.singularValueThreshold,
                                            .positionOnly = options.positionOnly && !options.sharpFeatures});
  v.intersections = static_cast<std::uint8_t>(n);
  v.rank = static_cast<std::uint8_t>(s.rank);
  if (!options.positionOnly)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) v.minNormalDot = std::min(v.minNormalDot, dot(normals[i], normals[j]));
  Vec3f x = s.point;
  if (options.sharpFeatures && s.rank == 2) x = slideIntoCell(x, s.freeDirections[0], cellOrigin, cellSize);
  const float slack = options.sharpFeatures ? kFeatureSlack : 1e-4f;  // else a rounding tolerance on the cell box
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    const float lo = static_cast<float>(cellOrigin[a]), hi = static_cast<float>(cellOrigin[a] + cellSize);
    if (!(x[a] >= lo - slack && x[a] <= hi + slack)) inside = false;
  }
  if (!inside || options.massPointOnly) {
    x = s.massPoint;
    v.massPointFallback = true;
  }
  // The mass point is a mean of edge points (inside up to rounding); a minimiser within the slack
  // moves onto the cell's boundary, no farther than the slack.
  for (int a = 0; a < 3; ++a)
    x[a] = std::clamp(x[a], static_cast<float>(cellOrigin[a]), static_cast<float>(cellOrigin[a] + cellSize));
  if (!options.positionOnly) v.qefError = inside && !options.sharpFeatures ? s.error : qefError(points, normals, x);
  for (int a = 0; a < 3; ++a) v.position[a] = x[a] + static_cast<float>(samples.origin[a]);
  return v;
}

}  // namespace isovdb::cell
