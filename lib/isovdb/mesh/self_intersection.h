// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file self_intersection.h
/// @brief Counts intersecting triangle pairs of a mesh with exact predicates.
///
/// Two triangles intersect when they have a point in common that is not
/// explained by the vertices they share, the rule of CGAL's
/// Polygon_mesh_processing::self_intersections:
/// - triangles sharing an edge (two vertex indices) intersect only when they
///   are coplanar and their opposite vertices lie on the same side of that
///   edge (one folds over the other);
/// - triangles sharing one vertex intersect only when the edge opposite that
///   vertex in one of them meets the other triangle (this covers the coplanar
///   overlap too);
/// - other pairs intersect when they have any point in common, touching included.
/// Sharing is by vertex index: two vertices at the same position are distinct
/// vertices, so weld first (weld.h). Two triangles with the same three indices
/// intersect; such copies meet every other triangle alike, so each set of copies
/// is tested once (k copies cost one test, not k^2/2). Degenerate triangles (a repeated index, or three collinear
/// points) are skipped; validateMesh() counts them.
///
/// All decisions use exact predicates (CGAL's Epick kernel) on the float
/// positions, so the result does not depend on rounding, on the thread count
/// or on the order of the triangles.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// @brief Counts the pairs of triangles that intersect (see the file comment).
///
/// Broad phase: a bounding-volume hierarchy over the triangles' boxes (boxes
/// sorted along a Morton curve and halved recursively, built and traversed
/// against itself in parallel with TBB); narrow phase: exact predicates on
/// each pair whose boxes touch. O(T log T) for meshes whose triangles overlap
/// few others (10 M triangles: about 7 s of CPU). Memory: about 75 bytes per
/// triangle at the peak (the sort that finds copies of a triangle included), plus
/// 8 per reported pair.
///
/// @param[in]  mesh   positions and triangles; normals are ignored
/// @param[out] pairs  when not null, cleared and filled with the intersecting
///                    pairs (smaller triangle index first), sorted
/// @return the number of intersecting pairs
/// @pre every triangle index is below `mesh.positions.size()`, and every
///      position is finite.
/// @throw InputError when a triangle references a missing vertex or a vertex
///        used by a triangle has a non-finite coordinate.
std::int64_t countSelfIntersections(const Mesh& mesh,
                                    std::vector<std::pair<std::uint32_t, std::uint32_t>>* pairs = nullptr);

/// @brief Whether two triangles over `mesh.positions` intersect, by the rule above
/// (shared vertex indices explain shared points). False when either is degenerate (a
/// repeated index, or collinear points). For local tests of triangles a caller is about to
/// place; countSelfIntersections is the whole-mesh count.
bool trianglesIntersect(const Mesh& mesh, const Triangle& a, const Triangle& b);

}  // namespace isovdb::mesh
