// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/triangle_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isovdb::mesh {

namespace {

Vec3d sub(const Vec3d& a, const Vec3d& b) noexcept { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3d& a, const Vec3d& b) noexcept { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d along(const Vec3d& a, const Vec3d& d, double t) noexcept {
  return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
Vec3d toDouble(const Vec3f& p) noexcept { return {p[0], p[1], p[2]}; }

/// Bins per axis at most (a quarter of a million in all: a meta-cell of 512 voxels, or one
/// block around a whole volume, keeps a small grid).
constexpr double kMaxBinsPerAxis = 64.0;

}  // namespace

Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) noexcept {
  // Voronoi regions of the vertices, then of the edges, else the face (Ericson 5.1.5).
  const Vec3d ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3d bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return along(a, ab, d1 / (d1 - d3));
  const Vec3d cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return along(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return a;  // a degenerate triangle: its vertex regions cover it
  const double v = vb / sum, w = vc / sum;
  return {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w};
}

TriangleGrid::TriangleGrid(const Mesh& mesh, double binSize) : mesh_(mesh), binSize_(binSize) {
  if (mesh.triangles.empty()) return;
  std::array<double, 3> hi{};
  for (int a = 0; a < 3; ++a) {
    lo_[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo_[a];
  }
  for (const Vec3f& p : mesh.positions)
    for (int a = 0; a < 3; ++a) {
      lo_[a] = std::min(lo_[a], static_cast<double>(p[a]));
      hi[a] = std::max(hi[a], static_cast<double>(p[a]));
    }
  double extent = 0.0;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo_[a]);
  binSize_ = std::max(binSize_, extent / kMaxBinsPerAxis);
  for (int a = 0; a < 3; ++a) bins_[a] = static_cast<int>((hi[a] - lo_[a]) / binSize_) + 1;
  // Two passes over each triangle's box of bins: count, then fill (CSR).
  boxes_.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int a = 0; a < 3; ++a) {
      const Triangle& v = mesh.triangles[t];
      boxes_[t][a] = std::min({mesh.positions[v[0]][a], mesh.positions[v[1]][a], mesh.positions[v[2]][a]});
      boxes_[t][a + 3] = std::max({mesh.positions[v[0]][a], mesh.positions[v[1]][a], mesh.positions[v[2]][a]});
    }
  const auto forBinsOf = [&](std::uint32_t t, auto&& visit) {
    const std::array<int, 3> b0 = binOf({boxes_[t][0], boxes_[t][1], boxes_[t][2]});
    const std::array<int, 3> b1 = binOf({boxes_[t][3], boxes_[t][4], boxes_[t][5]});
    for (int k = b0[2]; k <= b1[2]; ++k)
      for (int j = b0[1]; j <= b1[1]; ++j)
        for (int i = b0[0]; i <= b1[0]; ++i) visit(binIndex({i, j, k}));
  };
  firstOfBin_.assign(static_cast<std::size_t>(bins_[0]) * bins_[1] * bins_[2] + 1, 0);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) forBinsOf(t, [&](std::size_t b) { ++firstOfBin_[b + 1]; });
  for (std::size_t b = 1; b < firstOfBin_.size(); ++b) firstOfBin_[b] += firstOfBin_[b - 1];
  triangles_.resize(firstOfBin_.back());
  std::vector<std::uint32_t> next(firstOfBin_.begin(), firstOfBin_.end() - 1);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    forBinsOf(t, [&](std::size_t b) { triangles_[next[b]++] = t; });
}

std::array<int, 3> TriangleGrid::binOf(const std::array<double, 3>& p) const noexcept {
  std::array<int, 3> b{};
  for (int a = 0; a < 3; ++a) {
    // Beyond the grid (or NaN, from an infinite distance): the border bin.
    const double cell = std::floor((p[a] - lo_[a]) / binSize_);
    b[a] = cell >= bins_[a] - 1 ? bins_[a] - 1 : cell > 0.0 ? static_cast<int>(cell) : 0;
  }
  return b;
}

template <class Accept>
bool TriangleGrid::anyTriangleNear(const Vec3d& lo, const Vec3d& hi, double reach, Accept&& accept) const {
  if (triangles_.empty()) return false;
  // The bins the grown box overlaps; beyond the grid, the border bins, which hold every
  // triangle that could be within reach.
  const std::array<int, 3> b0 = binOf({lo[0] - reach, lo[1] - reach, lo[2] - reach});
  const std::array<int, 3> b1 = binOf({hi[0] + reach, hi[1] + reach, hi[2] + reach});
  for (int k = b0[2]; k <= b1[2]; ++k)
    for (int j = b0[1]; j <= b1[1]; ++j)
      for (int i = b0[0]; i <= b1[0]; ++i) {
        const std::size_t b = binIndex({i, j, k});
        for (std::uint32_t n = firstOfBin_[b]; n < firstOfBin_[b + 1]; ++n) {
          const std::array<float, 6>& box = boxes_[triangles_[n]];
          bool apart = false;
          for (int a = 0; a < 3; ++a) apart = apart || hi[a] < box[a] - reach || lo[a] > box[a + 3] + reach;
          if (!apart && accept(mesh_.triangles[triangles_[n]])) return true;
        }
      }
  return false;
}

std::vector<std::uint32_t> TriangleGrid::trianglesNear(const Vec3d& lo, const Vec3d& hi) const {
  std::vector<std::uint32_t> found;
  anyTriangleNear(lo, hi, 0.0, [&](const Triangle& t) {
    found.push_back(static_cast<std::uint32_t>(&t - mesh_.triangles.data()));
    return false;  // all of them
  });
  // A triangle binned in several of the box's bins came once per bin.
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

double TriangleGrid::squaredDistance(const Vec3d& q, const Triangle& t) const noexcept {
  const Vec3d d = sub(q, closestPointOnTriangle(q, toDouble(mesh_.positions[t[0]]), toDouble(mesh_.positions[t[1]]),
                                                toDouble(mesh_.positions[t[2]])));
  return dot(d, d);
}

double TriangleGrid::distanceTo(const Vec3f& p, std::uint32_t triangle) const {
  return std::sqrt(squaredDistance(toDouble(p), mesh_.triangles[triangle]));
}

bool TriangleGrid::within(const Vec3f& p, double distance, std::uint32_t* hint, double* found) const {
  const Vec3d q = toDouble(p);
  const double limit = distance * distance;
  double d2 = 0.0;
  const auto close = [&](const Triangle& t) {
    d2 = squaredDistance(q, t);
    return d2 <= limit;
  };
  const bool near = (hint != nullptr && *hint < mesh_.triangles.size() && close(mesh_.triangles[*hint])) ||
                    anyTriangleNear(q, q, distance, [&](const Triangle& t) {
                      if (!close(t)) return false;
                      if (hint != nullptr) *hint = static_cast<std::uint32_t>(&t - mesh_.triangles.data());
                      return true;
                    });
  if (near && found != nullptr) *found = std::sqrt(d2);
  return near;
}

}  // namespace isovdb::mesh
