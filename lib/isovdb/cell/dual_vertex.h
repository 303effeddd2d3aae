// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dual_vertex.h
/// @brief The dual vertex of an octree leaf: crossings on its bipolar edges,
///        Prewitt normals (or, with sharp features, the normals of the faces
///        beside a crease: crease_crossing.h), QEF minimised towards the mass
///        point, mass-point fallback when the minimiser leaves the cell
///        (paper 000, section 4.2.2).
///
/// Positions are global voxel index coordinates (meta-cell offsets plus
/// MetaCellSamples::origin). A vertex always lies in its cell (closed box).
/// Sign convention: inside iff value <= iso.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/cell/contour_settings.h"
#include "isovdb/cell/edge_intersection.h"
#include "isovdb/cell/qef.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::cell {

/// Options of the dual-vertex computation: what it reads of the ContourSettings
/// (dualVertexOptions()), and whether to skip the QEF.
struct DualVertexOptions {
  float iso = 0.0f;                     ///< isovalue; inside iff value <= iso
  float singularValueThreshold = 0.1f;  ///< QEF truncation, relative to the largest singular value (see QefOptions)
  /// Skip the QEF: the vertex is the mass point of the crossings. For a cell with several
  /// sheets (DMC groups), where a QEF minimiser can wander towards another sheet.
  bool massPointOnly = false;
  /// Sharp features (crease_crossing.h): crossings near a crease of the field are placed and
  /// oriented from the face they lie on. A crease line that grazes a cell's corner has its QEF
  /// minimiser nearest the mass point just outside the cell: a rank-2 minimiser slides along
  /// the crease into the cell, and one at most kFeatureSlack outside is clamped into it,
  /// rather than replaced by the mass point.
  bool sharpFeatures = false;
  /// Only the vertex's position (and valid()) are read: qefError and minNormalDot are left
  /// at their defaults, which saves a tenth of a vertex's cost where every cell has one.
  bool positionOnly = false;
};

/// The dual-vertex options the contour settings give.
inline DualVertexOptions dualVertexOptions(const ContourSettings& settings, bool massPointOnly = false) {
  return {.iso = settings.iso,
          .singularValueThreshold = settings.singularValueThreshold,
          .massPointOnly = massPointOnly,
          .sharpFeatures = settings.sharpFeatures};
}

/// How far (voxels) a QEF minimiser may lie outside its cell and still be clamped into it
/// with DualVertexOptions::sharpFeatures.
inline constexpr float kFeatureSlack = 0.1f;

/// @brief One dual vertex.
struct DualVertex {
  Vec3f position{0.0f, 0.0f, 0.0f};  ///< global voxel index coordinates, inside the cell
  float qefError = 0.0f;             ///< E(position), voxels^2
  std::uint16_t edges = 0;           ///< cell edges whose crossings were used (bit e, numbering of octree/morton.h)
  std::uint8_t intersections = 0;    ///< number of crossings used (0 = no vertex)
  std::uint8_t rank = 0;             ///< rank of the truncated QEF system
  bool massPointFallback = false;    ///< the QEF minimiser left the cell; the mass point was used
  float minNormalDot = 1.0f;         ///< smallest dot product of two crossing normals (1: all parallel)

  bool valid() const noexcept { return intersections > 0; }
  /// RMS distance (voxels) from the vertex to the tangent planes: sqrt(E / n).
  float rmsError() const noexcept;
};

/// @brief Dual vertex of the cell with min corner `cellOrigin` (meta-cell
///        offsets) and side `cellSize`, from the crossings on the cell edges in
///        `edgeMask` that are bipolar (regular-mode DMC passes one edge group
///        of its table per vertex; pass 0x0fff for all edges).
/// @return a vertex with intersections == 0 if none of those edges is bipolar.
/// @pre the cell lies in [0, S]^3.
DualVertex computeDualVertex(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                             std::uint16_t edgeMask, const DualVertexOptions& options = {});

/// @brief What computeDualVertex does once it has the crossings: the vertex of the
///        cell from `points` and unit `normals` (meta-cell offsets) on the cell
///        edges in `edges`.
DualVertex dualVertexFromCrossings(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                                   std::span<const Vec3f> points, std::span<const Vec3f> normals, std::uint16_t edges,
                                   const DualVertexOptions& options);

/// @brief The crossings `crossingOf(start, axis)` gives on the cell edges in `edgeMask`
///        (a pointer to the crossing on the cell edge from sample `start`, meta-cell
///        offsets, along `axis`; nullptr if that edge is not bipolar; read before the next
///        call), in edge order: their points and normals, `edges` the edges that had one.
/// @return how many there are.
template <class CrossingOf>
std::size_t gatherCrossings(std::array<int, 3> cellOrigin, int cellSize, std::uint16_t edgeMask,
                            CrossingOf&& crossingOf, std::array<Vec3f, 12>& points, std::array<Vec3f, 12>& normals,
                            std::uint16_t& edges) {
  std::size_t n = 0;
  edges = 0;
  for (int e = 0; e < 12; ++e) {
    if (!((edgeMask >> e) & 1)) continue;
    const int c0 = cellEdgeCorner(e, 0);
    const std::array<int, 3> start{cellOrigin[0] + (c0 & 1) * cellSize, cellOrigin[1] + ((c0 >> 1) & 1) * cellSize,
                                   cellOrigin[2] + ((c0 >> 2) & 1) * cellSize};
    const EdgeIntersection* hit = crossingOf(start, cellEdgeAxis(e));
    if (hit == nullptr) continue;
    points[n] = hit->point;
    normals[n] = hit->normal;
    ++n;
    edges = static_cast<std::uint16_t>(edges | (1u << e));
  }
  return n;
}

/// @brief computeDualVertex with the crossings found by `crossingOf(start, axis)`
///        (as gatherCrossings reads them): lets a caller look up crossings it found once.
template <class CrossingOf>
DualVertex dualVertexOfCrossings(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                                 std::uint16_t edgeMask, const DualVertexOptions& options, CrossingOf&& crossingOf) {
  std::array<Vec3f, 12> points;
  std::array<Vec3f, 12> normals;
  std::uint16_t edges = 0;
  const std::size_t n = gatherCrossings(cellOrigin, cellSize, edgeMask, crossingOf, points, normals, edges);
  return dualVertexFromCrossings(samples, cellOrigin, cellSize, std::span<const Vec3f>(points.data(), n),
                                 std::span<const Vec3f>(normals.data(), n), edges, options);
}

/// @brief Dual vertex from all bipolar edges of the cell.
inline DualVertex computeDualVertex(const cell::MetaCellSamples& samples, std::array<int, 3> cellOrigin, int cellSize,
                                    const DualVertexOptions& options = {}) {
  return computeDualVertex(samples, cellOrigin, cellSize, 0x0fff, options);
}

}  // namespace isovdb::cell
