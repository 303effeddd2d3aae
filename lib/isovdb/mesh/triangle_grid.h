// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file triangle_grid.h
/// @brief A mesh's triangles binned in a uniform grid, to ask whether a point lies
///        within a given distance of the surface: adaptive mode's error bound asks
///        it of the full-resolution vertices inside every coarse leaf
///        (contour/error_bound.h), hundreds of thousands of times per meta-cell; and
///        which triangles lie in a box (reservoir/untangle_loops.h).
///
/// A yes/no question with a small radius is cheaper than a nearest-triangle search
/// (CGAL's AABB tree, which `isovdb compare` uses): it visits the bins the query
/// box overlaps and stops at the first triangle close enough. Distances are exact
/// point-triangle distances in double precision (Ericson, Real-Time Collision
/// Detection, 5.1.5).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// @brief The closest point to `p` on the triangle (a, b, c).
Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) noexcept;

class TriangleGrid {
 public:
  /// @brief Bins the triangles of `mesh` (which must outlive the grid) in cubes of
  ///        side `binSize` (> 0, mesh units) over the mesh's bounding box, or larger
  ///        ones where that would take more than 64 bins along an axis.
  TriangleGrid(const Mesh& mesh, double binSize);

  /// True if some triangle of the mesh lies within `distance` of `p`. `hint` (optional,
  /// in and out) is a triangle to try first and receives the one found: queries that
  /// walk along the surface mostly find the previous answer close enough again.
  /// `found` (optional) receives the distance to the triangle found.
  bool within(const Vec3f& p, double distance, std::uint32_t* hint = nullptr, double* found = nullptr) const;

  /// The exact distance from `p` to the mesh's triangle `triangle` (an index, as `hint`).
  double distanceTo(const Vec3f& p, std::uint32_t triangle) const;

  /// The triangles whose bounding boxes meet the box [lo, hi], each once, in index order
  /// (untangle_loops: the triangles around a loop, without a pass over the whole mesh).
  std::vector<std::uint32_t> trianglesNear(const Vec3d& lo, const Vec3d& hi) const;

 private:
  const Mesh& mesh_;
  double binSize_;
  std::array<double, 3> lo_{0.0, 0.0, 0.0};
  std::array<int, 3> bins_{0, 0, 0};
  // CSR: the triangles of bin b are triangles_[firstOfBin_[b] .. firstOfBin_[b + 1]).
  std::vector<std::uint32_t> firstOfBin_;
  std::vector<std::uint32_t> triangles_;
  std::vector<std::array<float, 6>> boxes_;  // per triangle: min x, y, z, max x, y, z (a cheap rejection)

  std::array<int, 3> binOf(const std::array<double, 3>& p) const noexcept;
  /// Squared distance from `q` to the triangle `t` of the mesh.
  double squaredDistance(const Vec3d& q, const Triangle& t) const noexcept;
  /// Calls `accept(triangle)` for each triangle binned where the box [lo, hi] grown by
  /// `reach` lies and whose own box reaches it, until `accept` returns true; returns that.
  template <class Accept>
  bool anyTriangleNear(const Vec3d& lo, const Vec3d& hi, double reach, Accept&& accept) const;
  std::size_t binIndex(const std::array<int, 3>& b) const noexcept {
    return (static_cast<std::size_t>(b[2]) * static_cast<std::size_t>(bins_[1]) + static_cast<std::size_t>(b[1])) *
               static_cast<std::size_t>(bins_[0]) +
           static_cast<std::size_t>(b[0]);
  }
};

}  // namespace isovdb::mesh
