// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file pn_tessellation.h
/// @brief Adaptive tessellation of a mesh into curved PN triangles (paper 003
/// §4.3–4.4): a factor per edge from the angle between its two vertex normals
/// (the linear or the exponential rule of Table 4.1, at most `maxFactor`),
/// each triangle refined at the largest factor of its edges, the points on an
/// edge snapped to that edge's own factor so both triangles of an edge put the
/// same points there (no cracks: a closed mesh stays closed). Normals of the
/// new vertices are envelope normals.
#pragma once

#include <cstdint>

#include "isovdb/mesh/mesh.h"
#include "isovdb/reservoir/corner_point_grid.h"

namespace isovdb::reservoir {

enum class FactorRule {
  Linear,       ///< l = k (1 - t) / 2, t = n_i . n_j
  Exponential,  ///< e = 6^(1/t'') - 5, t' = (t + 1) / 2, t'' = 0.45 (1 - t') + t'
};

/// Subdivisions of an edge before rounding and clamping (Table 4.1's e(t'') or l(t')).
double edgeSubdivisions(double cosine, int maxFactor, FactorRule rule);
/// The integer factor of an edge: ceil of edgeSubdivisions clamped to [1, maxFactor].
int edgeFactor(const Vec3d& ni, const Vec3d& nj, int maxFactor, FactorRule rule);

struct TessellationOptions {
  int maxFactor = 8;  ///< k, the most segments an edge is cut into
  FactorRule rule = FactorRule::Exponential;
  double inflation = 0.25;  ///< envelope offset, times the mean edge length
  /// Where the curved patches cross others (exact predicates on the tessellated mesh), the
  /// edges of their input triangles become straight (the chord, in both triangles of the
  /// edge) and the mesh is tessellated again, while a pass straightens something. Bulges
  /// of metres over 100 m triangles crossed Reek's 3 m layers (PORO 0.21, k = 3: 11,792
  /// pairs). Normals stay the envelope's: the straightened parts still shade smoothly.
  bool straightenCrossings = true;
  int maxStraighteningPasses = 8;
};

struct TessellationResult {
  mesh::Mesh mesh;
  std::int64_t edges = 0;
  double meanFactor = 0;  ///< over the input edges
  std::int64_t pairsBefore = 0;    ///< self-intersecting pairs of the first tessellation
  std::int64_t pairsAfter = 0;     ///< and of the last (straightenCrossings)
  std::int64_t straightEdges = 0;  ///< input edges kept as chords
};

/// @pre `input` has one unit normal per vertex. Deterministic.
TessellationResult tessellatePn(const mesh::Mesh& input, const TessellationOptions& options = {});

}  // namespace isovdb::reservoir
