// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file quad_diagonal.h
/// @brief Which diagonal splits a quadrilateral of dual vertices into the better
///        pair of triangles.
///
/// Regular mode's quads and adaptive mode's four-corner polygons ask the same
/// question, and must answer it alike: adaptive mode's error bound is measured
/// against regular mode's mesh, and at the finest leaves (which it cannot split)
/// the two meshes share their vertices. A quad that is not planar gives two
/// surfaces up to about half a voxel apart, so the other diagonal there broke
/// the bound (a 96^3 blobs mask at --max-error 0.25: 0.32 voxel).
#pragma once

#include <Eigen/Core>

namespace isovdb::contour {

/// @brief True when diagonal p0-p2 of the quadrilateral p0 p1 p2 p3 (cyclic order) gives
///        triangles whose worse one is at least as good as with diagonal p1-p3 (shape
///        quality: twice the area over the sum of the squared edge lengths; 0 = degenerate). Symmetric in each
///        diagonal's ends and in the cycle's direction.
bool firstDiagonalIsBetter(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           const Eigen::Vector3d& p3) noexcept;

}  // namespace isovdb::contour
