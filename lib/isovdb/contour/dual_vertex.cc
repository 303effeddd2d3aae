#include "isovdb/contour/dual_vertex.h"

#include <algorithm>
#include <cmath>

#include "isovdb/contour/edge_intersection.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {

float DualVertex::rmsError() const noexcept {
  return intersections > 0 ? std::sqrt(std::max(qefError, 0.0f) / static_cast<float>(intersections)) : 0.0f;
}

DualVertex computeDualVertex(const octree::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                             std::uint16_t edgeMask, const DualVertexOptions& options) {
  DualVertex v;
  std::array<Vec3f, 12> points;
  std::array<Vec3f, 12> normals;
  std::size_t n = 0;
  for (int e = 0; e < 12; ++e) {
    if (!((edgeMask >> e) & 1)) continue;
    const int c0 = octree::cellEdgeCorner(e, 0), c1 = octree::cellEdgeCorner(e, 1);
    const std::array<int, 3> p0{cellOrigin[0] + (c0 & 1) * cellSize, cellOrigin[1] + ((c0 >> 1) & 1) * cellSize,
                                cellOrigin[2] + ((c0 >> 2) & 1) * cellSize};
    const std::array<int, 3> p1{cellOrigin[0] + (c1 & 1) * cellSize, cellOrigin[1] + ((c1 >> 1) & 1) * cellSize,
                                cellOrigin[2] + ((c1 >> 2) & 1) * cellSize};
    if (octree::isInside(samples.value(p0), options.iso) == octree::isInside(samples.value(p1), options.iso))
      continue;  // not bipolar
    EdgeIntersection hit;
    if (!intersectEdge(samples, p0, octree::cellEdgeAxis(e), cellSize, options.iso, hit)) continue;
    points[n] = hit.point;
    normals[n] = hit.normal;
    ++n;
    v.edges = static_cast<std::uint16_t>(v.edges | (1u << e));
  }
  if (n == 0) return v;
  const QefSolution s = solveQef(std::span<const Vec3f>(points.data(), n), std::span<const Vec3f>(normals.data(), n),
                                 QefOptions{.singularValueThreshold = options.singularValueThreshold});
  v.intersections = static_cast<std::uint8_t>(n);
  v.rank = static_cast<std::uint8_t>(s.rank);
  Vec3f x = s.point;
  constexpr float kSlack = 1e-4f;  // rounding tolerance on the cell box
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    const float lo = static_cast<float>(cellOrigin[a]), hi = static_cast<float>(cellOrigin[a] + cellSize);
    if (!(x[a] >= lo - kSlack && x[a] <= hi + kSlack)) inside = false;
  }
  if (!inside || options.massPointOnly) {
    x = s.massPoint;
    v.massPointFallback = true;
  }
  for (int a = 0; a < 3; ++a)  // the mass point is a mean of edge points: inside up to rounding
    x[a] = std::clamp(x[a], static_cast<float>(cellOrigin[a]), static_cast<float>(cellOrigin[a] + cellSize));
  v.qefError = inside ? s.error
                      : qefError(std::span<const Vec3f>(points.data(), n), std::span<const Vec3f>(normals.data(), n), x);
  for (int a = 0; a < 3; ++a) v.position[a] = x[a] + static_cast<float>(samples.origin[a]);
  return v;
}

}  // namespace isovdb::contour
