// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file ju_udeshi.h
/// @brief Intersection-free polygons of octree dual contouring: the envelope
///        of a minimal edge, its geometric tests and the fan through the edge
///        point v_e, the face points v_f and the cell vertices v_c
///        (paper 000, section 4.2.3.2; Ju & Udeshi 2006, "Intersection-free
///        contouring on an octree grid").
///
/// Around a sign-changing minimal edge e = [e0, e1] lie k = 4 leaves (a quad)
/// or k = 3 leaves, one of them coarser (a triangle). Between consecutive
/// cells c_i and c_{i+1} lies a minimal face f_i (the face of the smaller of
/// the two cells) that contains e on its boundary. The envelope of e is the
/// union of the 2k tetrahedra conv(e0, e1, v_{c_i}, v_{f_i}) and
/// conv(e0, e1, v_{c_{i+1}}, v_{f_i}). When every v_c lies strictly inside its
/// cell and every v_f strictly inside its face, the envelopes of different
/// minimal edges have disjoint interiors (they tile the cells), so a surface
/// whose polygons stay inside their edge's envelope has no self-intersection.
///
/// Per face (the same answer for every edge on the face's boundary): if the
/// segment v_{c_i} v_{c_{i+1}} crosses f_i strictly inside it, v_f is that
/// crossing (collinear with the two cell vertices) and the face is "crossed";
/// otherwise v_f is the crossing clamped into the face and becomes a mesh
/// vertex that every edge of the face routes its polygon through. Per edge: a
/// triangulation of that polygon from one of its vertices (the trivial one
/// when every face is crossed) is kept if it lies inside the envelope (sector
/// clipping in double precision with a safety margin); otherwise the fan
/// through v_e (v_e, v_c_i, v_f_i), (v_e, v_f_i, v_c_{i+1}) is used, which lies
/// in the envelope by construction.
///
/// Positions are any consistent Cartesian coordinates (the contourer uses
/// global voxel index coordinates). Everything here is deterministic and
/// thread-safe (pure functions).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/vec3.h"

namespace isovdb::contour {

/// Double-precision point / vector.
using isovdb::Vec3d;

/// Cells, faces and edge of one sign-changing minimal edge, in cyclic order.
struct EdgeEnvelope {
  Vec3d edgeStart{0, 0, 0};           ///< e0
  Vec3d edgeEnd{0, 0, 0};             ///< e1
  int cellCount = 4;                  ///< k: 4 (quad) or 3 (triangle)
  std::array<Vec3d, 4> cellPoints{};  ///< v_c of cell i, cyclic order around e (first k used)
  std::array<Vec3d, 4> facePoints{};  ///< v_f of the face between cell i and cell (i + 1) mod k
};

/// A minimal face: an axis-aligned square on the plane x[axis] = coordinate.
struct MinimalFace {
  int axis = 0;             ///< normal axis
  double coordinate = 0.0;  ///< plane position on `axis`
  Vec3d min{0, 0, 0};       ///< min corner (its `axis` entry is ignored)
  double size = 1.0;        ///< side length
};

/// The face between two neighbouring cells around an edge (faceBetweenQuadrants).
struct QuadrantFace {
  MinimalFace face;
  bool firstOnMinSide = false;  ///< the first cell lies on the face's min side
};

/// @brief The face shared by the cells of quadrants `q` and `next` (they differ in one bit:
///        bit 0 = +u side, bit 1 = +v side, as cell::edgeQuadrantVoxel) around the edge from
///        `edgeStart` along `axis`, cells of side `size`: on the plane of the edge across
///        which they differ, spanning the edge and the cells' side away from it.
inline QuadrantFace faceBetweenQuadrants(const std::array<int, 3>& edgeStart, int axis, int size, int q, int next) {
  const auto uv = cell::otherAxes(axis);
  const int bit = (q ^ next) == 1 ? 0 : 1, other = 1 - bit;
  const int n = uv[static_cast<std::size_t>(bit)], m = uv[static_cast<std::size_t>(other)];
  QuadrantFace result;
  result.face.axis = n;
  result.face.coordinate = edgeStart[static_cast<std::size_t>(n)];
  result.face.size = size;
  for (int a = 0; a < 3; ++a) result.face.min[a] = edgeStart[static_cast<std::size_t>(a)];
  if (((q >> other) & 1) == 0) result.face.min[m] -= size;
  result.firstOnMinSide = ((q >> bit) & 1) == 0;
  return result;
}

/// The point v_f of a minimal face and whether the cell-to-cell segment crosses the face.
struct FacePoint {
  Vec3d point{0, 0, 0};  ///< on the face plane, strictly inside the face
  bool crossed = false;  ///< v_f is the crossing of the segment between the two cell vertices
};

/// Tolerances of the envelope test (lengths in the unit of the positions, voxels).
struct EnvelopeOptions {
  /// A point of a trivial triangle must lie at least this far inside the
  /// envelope faces that other edges' envelopes share (except at v_c, v_f and
  /// on the segment between them, which neighbours share by construction).
  /// Larger = more fans, safer against float rounding of the output.
  double margin = 1e-4;
  /// Fraction of the face side that v_f keeps away from the face boundary
  /// (a crossing closer than this to the boundary counts as not crossed).
  double faceMarginFraction = 1e-3;
};

/// How the polygon of one minimal edge is triangulated. The polygon visits the
/// cell vertices c_0 .. c_{k-1} and, after c_i, the face point f_i of every
/// face i that is not crossed (the segment c_i c_{i+1} misses it, so the
/// polygon must go through f_i); m = k + (uncrossed faces) vertices.
struct EdgeTriangulation {
  bool fan = false;  ///< true: m triangles (v_e, p_j, p_{j+1}) through the edge point v_e
  int apex = 0;      ///< fan = false: m - 2 triangles (p_apex, p_{apex+j}, p_{apex+j+1})
};

/// Local vertex numbering of an edge's triangles: cells 0..3, faces 4..7 (kFaceVertex + i), edge point 8.
inline constexpr int kFaceVertex = 4;
inline constexpr int kEdgeVertex = 8;

/// @brief computeFacePoint's answer in every case, computed in full (the clamp, and the rim
///        point where the segment misses the face far away); callers use computeFacePoint.
FacePoint clampedFacePoint(const Vec3d& a, const Vec3d& b, const MinimalFace& face, const EnvelopeOptions& options);

/// @brief v_f of a minimal face between the cell vertices `a` and `b`, which lie
///        on opposite sides of the face plane (paper 000, section 4.2.3.2).
/// @param[in] a, b  the two cell vertices; the result depends only on the unordered
///                  pair when callers pass them in a canonical order (min side first).
/// @param[in] face  the minimal face.
/// @param[in] options  faceMarginFraction.
/// @return the crossing of segment ab with the face if it lies inside the face
///         shrunk by the margin (crossed = true), else that crossing (or the
///         midpoint projected on the plane if ab does not cross it) clamped into it.
///
/// Inline where the segment crosses the face within its margin (almost every face: four per
/// quad, out of line this was a fifth of regular mode's quads), the same arithmetic as
/// clampedFacePoint; every other case is clampedFacePoint's.
inline FacePoint computeFacePoint(const Vec3d& a, const Vec3d& b, const MinimalFace& face,
                                  const EnvelopeOptions& options = {}) {
  const int n = face.axis;
  const double da = a[n] - face.coordinate, db = b[n] - face.coordinate;
  if ((da < 0) != (db < 0)) {
    const double t = da / (da - db);
    FacePoint result{{a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t}, true};
    result.point[n] = face.coordinate;
    const double m = options.faceMarginFraction * face.size;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == n) continue;
      const double lo = face.min[axis] + m, hi = face.min[axis] + face.size - m;
      if (result.point[axis] < lo || result.point[axis] > hi) result.crossed = false;
    }
    if (result.crossed) return result;
  }
  return clampedFacePoint(a, b, face, options);
}

/// @brief True if the triangle (a, b, c) lies inside the envelope of `envelope`,
///        touching the envelope faces shared with other edges only on the
///        segments v_c v_f, which neighbours share by construction
///        (Ju & Udeshi 2006, envelope test).
///
/// Each tetrahedron's angular sector around the edge line clips the triangle;
/// every vertex of the clipped polygon must be inside that tetrahedron, at
/// least options.margin away from its two faces opposite the edge's ends.
/// @pre cell points strictly inside their cells, face points strictly inside their faces
///      (the tetrahedra are not degenerate); otherwise the answer is false.
bool triangleInEnvelope(const EdgeEnvelope& envelope, const Vec3d& a, const Vec3d& b, const Vec3d& c,
                        const EnvelopeOptions& options = {});

/// @brief True when the quad of a four-cell edge's cell points (cyclic order, no face
///        points), split along one of its diagonals, lies in the envelope: regular mode's test
///        before it fans through the edge's crossing (voxelQuadTriangles). The sectors are
///        built once for the up to four triangles.
bool plainQuadInEnvelope(const EdgeEnvelope& envelope, const EnvelopeOptions& options = {});

/// @brief A sufficient condition for triangleInEnvelope to keep every triangle of an
///        edge's polygon with every face crossed: the quad (k = 4) split from cell vertex
///        `apex` (0 or 1), or the triangle (k = 3, apex 0), decided without clipping: true
///        only where each point the envelope test checks lies at least 2 * options.margin
///        inside (so the full test accepts it too, whatever its rounding); false where the
///        full test must decide.
///
/// The edge is axis-aligned, so every sector plane contains the edge direction: seen along
/// the edge, the envelope is 2k wedges around the edge point O (a cell point's ray, a
/// face point's ray, ...), and over a point at parameter beta of a ray R the tetrahedra
/// span heights [beta R_w, beta R_w + (1 - beta) s] (s the edge's length). The clipped
/// triangles' corners that are not on a segment v_c v_f are the diagonal's crossings of
/// the rays on one side of O, and O itself under the triangle whose shadow contains O; the
/// test checks those heights against the tetrahedra's bounds, with each outer plane's tilt
/// bounded by |P - e| |Q - e| / |(P - e) x (Q - e)|_w, or taken from the plane's normal
/// where that bound refuses. With three cells only the point over O is checked: it lies
/// between the larger cell's two face points, on their plane.
/// @pre every face crossed (f_i on the segment c_i c_{i+1}, as computeFacePoint's crossed
///      face points are).
bool clearlyInsideEnvelope(const EdgeEnvelope& envelope, int apex, const EnvelopeOptions& options = {});

/// @brief The polygon of an edge as local vertex numbers (see kFaceVertex):
///        c_0, [f_0], c_1, [f_1], ... with f_i present iff face i is not crossed.
/// @param[in] cellCount  k (3 or 4).
/// @param[in] facesCrossed  per face i (first k).
std::vector<int> edgePolygon(int cellCount, const std::array<bool, 4>& facesCrossed);

/// @brief Chooses the triangulation of one edge's polygon.
///
/// Ju–Udeshi: a triangulation of the polygon from one of its vertices is kept
/// if all its triangles lie inside the envelope (quads: the shorter diagonal
/// first; larger polygons: apexes in order); otherwise the fan through v_e is
/// used, which lies in the envelope by construction. For a crossed face f_i lies
/// on the segment c_i c_{i+1}, so the fan's two triangles (v_e, c_i, f_i),
/// (v_e, f_i, c_{i+1}) are the single triangle (v_e, c_i, c_{i+1}); with every
/// face uncrossed it is the full fan of 2k = 6 or 8 triangles.
/// @param[in] envelope  edge, cell points and face points.
/// @param[in] facesCrossed  per face i (first k): computeFacePoint(...).crossed.
/// @param[in] intersectionFree  false: plain dual contouring (every face treated
///            as crossed, no test; quads split along the shorter diagonal).
/// @param[in] firstApex  for a quad with every face crossed: the apex (0 or 1) tried first,
///            where not the one of the cells' better diagonal (-1).
EdgeTriangulation chooseTriangulation(const EdgeEnvelope& envelope, const std::array<bool, 4>& facesCrossed,
                                      bool intersectionFree = true, const EnvelopeOptions& options = {},
                                      int firstApex = -1);

/// @brief Triangles (local vertex numbers, see kFaceVertex / kEdgeVertex) of an
///        edge's polygon, in the polygon's orientation.
/// @param[in] cellCount  k (3 or 4).
/// @param[in] facesCrossed  as given to chooseTriangulation (all true for plain DC).
/// @param[in] how  the triangulation.
/// @param[out] out  cleared, then filled: m - 2 triangles, or m with the fan.
void triangulateEdge(int cellCount, const std::array<bool, 4>& facesCrossed, EdgeTriangulation how,
                     std::vector<std::array<int, 3>>& out);

}  // namespace isovdb::contour
