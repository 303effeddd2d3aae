// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_distance.h
/// @brief How far two meshes of the same surface are apart: the two-sided
///        Hausdorff distance, sampled (`isovdb compare`; adaptive mode's error
///        bound is checked against regular mode's mesh with it).
///
/// Each mesh is sampled (every vertex a triangle uses, plus a barycentric grid
/// on every triangle whose longest edge exceeds the spacing) and each sample's
/// distance to the other mesh is found in an AABB tree of its triangles
/// (CGAL's AABB_tree). A point of a triangle lies within spacing / sqrt(3) of a
/// sample (the circumradius of a grid triangle), and distance is 1-Lipschitz,
/// so the true one-sided distance is at most the sampled maximum plus that.
/// Deterministic: the samples and their order do not depend on the threads.
#pragma once

#include <cstddef>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// Distances from the samples of one mesh to the other (mesh units).
struct OneSidedDistance {
  std::size_t samples = 0;
  double mean = 0.0;
  double p99 = 0.0;               ///< 99th percentile
  double max = 0.0;               ///< the sampled one-sided Hausdorff distance
  Vec3d farthest{0.0, 0.0, 0.0};  ///< the sample where it is reached (the first such, in sample order)
};

/// Both directions, and the sampling they used.
struct MeshDistance {
  OneSidedDistance aToB;  ///< from points of A to the surface of B
  OneSidedDistance bToA;
  double spacing = 0.0;  ///< sample spacing (mesh units)
  /// The sampled two-sided Hausdorff distance.
  double hausdorff() const noexcept { return aToB.max > bToA.max ? aToB.max : bToA.max; }
  /// What the samples guarantee: the true Hausdorff distance is at most this.
  double upperBound() const noexcept;
};

/// Options of compareMeshes.
struct MeshDistanceOptions {
  double spacing = 0.25;  ///< largest gap between samples on a triangle (mesh units)
};

/// @brief The two-sided sampled Hausdorff distance between `a` and `b`.
/// @throw InputError if a mesh has no triangles, an index is out of range, or
///        the spacing is not positive.
MeshDistance compareMeshes(const Mesh& a, const Mesh& b, const MeshDistanceOptions& options = {});

}  // namespace isovdb::mesh
