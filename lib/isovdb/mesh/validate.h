// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file validate.h
/// @brief Topological and geometric checks of a triangle mesh: closed,
///        manifold, consistently oriented, Euler characteristic and genus per
///        connected component, degenerate triangles and self-intersections.
///
/// Topology is combinatorial: vertices are identified by index, so weld
/// (weld.h) before validating a soup. An edge is an unordered pair of vertex
/// indices used by at least one triangle.
///
/// Triangles with a repeated index ("collapsed") count in `triangles` and
/// `degenerateTriangles` only; every other figure is that of the mesh without
/// them. Triangles whose three distinct vertices are collinear or coincident
/// take part in the topology (they are combinatorially valid) and count in
/// `degenerateTriangles`; the self-intersection test skips both kinds.
#pragma once

#include <cstdint>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// Figures of one connected component (triangles connected through shared vertices).
struct ComponentReport {
  std::int64_t triangles = 0;
  std::int64_t vertices = 0;  ///< vertices its triangles reference
  std::int64_t edges = 0;
  std::int64_t eulerCharacteristic = 0;  ///< vertices - edges + triangles
  bool closed = false;                   ///< no boundary edge and no non-manifold edge
  bool manifold = false;                 ///< no non-manifold edge and no non-manifold vertex
  /// (2 - χ) / 2 for a closed manifold component; -1 otherwise, and -1 when
  /// 2 - χ is odd (a non-orientable surface such as RP²).
  std::int64_t genus = -1;
  /// Volume enclosed, signed: positive when a closed component's triangles face
  /// outward (counter-clockwise seen from outside), negative for a cavity's or an
  /// inside-out one's; meaningless for an open component.
  double signedVolume = 0.0;
};

/// What validateMesh() found. Counts are exact; see the file comment for
/// how collapsed triangles are treated.
struct MeshReport {
  std::int64_t vertices = 0;            ///< mesh.positions.size()
  std::int64_t referencedVertices = 0;  ///< vertices used by at least one triangle
  std::int64_t triangles = 0;           ///< mesh.triangles.size(), collapsed ones included
  std::int64_t edges = 0;
  std::int64_t boundaryEdges = 0;     ///< edges of exactly one triangle
  std::int64_t nonManifoldEdges = 0;  ///< edges of more than two triangles
  /// Vertices whose incident triangles, joined through the edges they share
  /// at that vertex, form more than one fan (the umbrella test); each counted once.
  std::int64_t nonManifoldVertices = 0;
  /// Edges of exactly two triangles that both traverse it in the same direction.
  std::int64_t inconsistentlyOrientedEdges = 0;
  /// Triangles with a repeated index, or whose three points are collinear or
  /// coincident (CGAL's exact `collinear`).
  std::int64_t degenerateTriangles = 0;
  std::int64_t components = 0;           ///< connected through shared vertices
  std::int64_t eulerCharacteristic = 0;  ///< referencedVertices - edges + triangles (not collapsed)
  double signedVolume = 0.0;             ///< sum of the components' (ComponentReport::signedVolume)
  /// Intersecting triangle pairs (self_intersection.h); -1 when not checked.
  std::int64_t selfIntersectingPairs = -1;
  bool closed = true;    ///< no boundary edge and no non-manifold edge (true for an empty mesh)
  bool manifold = true;  ///< no non-manifold edge and no non-manifold vertex
  /// One per component, in the order of each component's first triangle.
  std::vector<ComponentReport> componentReports;
};

struct ValidateOptions {
  /// Count intersecting triangle pairs. This is the most expensive check
  /// (about as long as all the others together on a large mesh); when false,
  /// `MeshReport::selfIntersectingPairs` stays -1.
  bool selfIntersections = true;
};

/// @brief Checks the topology and geometry of `mesh` (see MeshReport).
///
/// Parallel (TBB) and deterministic: the report does not depend on the
/// thread count. O(T) time for the topology (plus a sort of each vertex's
/// umbrella), O(T log T) for the self-intersections; memory about 25 bytes
/// per triangle and 32 per vertex, then countSelfIntersections()'s when
/// enabled. 10 M triangles take about 2.5 s of CPU without
/// self-intersections and 9 s with them.
///
/// @param[in] mesh     positions and triangles; normals are ignored
/// @param[in] options  which checks to run
/// @pre every triangle index is below `mesh.positions.size()`, every position
///      used by a triangle is finite, and there are fewer than 2^32 - 1 triangles.
/// @throw InputError when one of those does not hold (naming the first
///        offending triangle).
MeshReport validateMesh(const Mesh& mesh, const ValidateOptions& options = {});

}  // namespace isovdb::mesh
