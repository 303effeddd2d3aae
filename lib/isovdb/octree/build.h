// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file build.h
/// @brief Top-down construction of a meta-cell's linear octree with the
///        topological criteria, regular or adaptive (paper 000, section 4.2.1).
///
/// Uniform subdivision down to the minimum depth, then complex cells
/// (criteria.h) are subdivided up to the maximum depth.
/// - Regular: every heterogeneous cell is subdivided too, so every leaf the
///   surface crosses is at the maximum depth (for Dual Marching Cubes).
/// - Adaptive: only complex cells, and cells whose corner configuration has
///   several Dual Marching Cubes groups or a doubled ambiguous face (one dual
///   vertex cannot stand for them) or that hide a component of samples inside
///   (criteria.h, hasHiddenComponent), are subdivided; the tree is then kept 2:1
///   balanced (leaves that share a face, an edge or a corner differ by at most
///   one depth); optionally a geometric criterion (QEF error above a
///   tolerance; with sharp features, a vertex off a curved crease) refines
///   further. For octree dual contouring + Ju–Udeshi.
/// Memory: O(leaves) beside the dense cell::MetaCellSamples block. Deterministic:
/// the result does not depend on the number of threads.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isovdb/octree/linear_octree.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/progress.h"

namespace isovdb::octree {

/// Which cells are subdivided between the minimum and the maximum depth.
enum class OctreeConstruction {
  Regular,   ///< complex and heterogeneous cells: all surface leaves at the maximum depth (manifold DMC)
  Adaptive,  ///< complex cells only, 2:1 balanced (+ optional geometric criterion) (DC + Ju–Udeshi)
};

/// Options of buildOctree. Depths count from the meta-cell root (0); a depth d
/// has cells of S >> d voxels. Cell-size fields, when > 0, override the depths.
struct OctreeOptions {
  OctreeConstruction construction = OctreeConstruction::Adaptive;  ///< regular or adaptive construction
  int minDepth = 2;            ///< uniform subdivision down to this depth (CLI --min-level); larger = more small leaves
  int maxDepth = -1;           ///< deepest depth (CLI --max-level); -1 = 1-voxel cells
  int maxCellSize = 0;         ///< if > 0: largest leaf size in voxels (power of two), overrides minDepth
  int finestCellSize = 0;      ///< if > 0: smallest leaf size in voxels (power of two), overrides maxDepth
  float qefTolerance = -1.0f;  ///< adaptive only: also subdivide a surface leaf whose dual vertex is farther
                               ///< than this RMS distance (voxels) from its tangent planes; < 0 = off
  float singularValueThreshold = 0.1f;  ///< QEF truncation used by the geometric criterion (see cell::QefOptions)
  /// Adaptive, with the QEF criterion on: sharp features (cell::DualVertexOptions::sharpFeatures
  /// for the criterion's vertices), and also subdivide a surface leaf whose crossing normals are
  /// more than 60 degrees apart and whose dual vertex is at least `featureTolerance` voxels off
  /// the zero level by the field's Lipschitz bound (surface_gap.h): on a curved rim the tangent
  /// planes of a coarse leaf meet outside the rim, with an almost exact fit. Contouring must
  /// use the same setting (contour::AdaptiveContourOptions::sharpFeatures).
  bool sharpFeatures = false;
  float featureTolerance = 0.05f;        ///< voxels; see sharpFeatures
  float iso = 0.0f;                      ///< isovalue; a sample is inside iff value <= iso
  bool detectInteriorComponents = true;  ///< a cell with one-phase faces but a sample of the other phase inside
                                         ///< is complex (catches blobs that touch no face; one pass over such cells)
  bool parallel = true;                  ///< evaluate each level's cells with TBB (the result is the same)
};

/// Depths after resolving cell sizes against the meta-cell size.
struct OctreeDepths {
  int minDepth = 0;
  int maxDepth = 0;
};

/// @brief Resolves depths and cell sizes of `options` for a meta-cell of `metaCellSize` voxels.
/// @throw InputError if a size is not a power of two <= metaCellSize or minDepth > maxDepth.
OctreeDepths resolveDepths(const OctreeOptions& options, int metaCellSize);

/// What the construction did (figures for statistics and tests).
struct OctreeBuildStats {
  std::vector<std::size_t> cellsClassified;  ///< per depth: cells whose criteria were evaluated
  std::size_t complexEdges = 0;              ///< complex cell edges found (an edge shared by k cells counts k times)
  std::size_t complexFaces = 0;              ///< complex cell faces found (same)
  std::size_t interiorComponents = 0;        ///< cells complex only through an interior component
  std::size_t complexCells = 0;              ///< complex cells found (subdivided or left at the maximum depth)
  std::size_t unresolvedComplexLeaves = 0;   ///< complex leaves at the maximum depth
  std::size_t geometricSplits = 0;           ///< cells subdivided by the QEF criterion
  std::size_t featureSplits = 0;             ///< of them, by the sharp-feature gap (OctreeOptions::sharpFeatures)
  std::size_t multiSheetSplits = 0;          ///< adaptive: cells subdivided because their configuration has several
                                     ///< DMC groups or a doubled ambiguous face (one vertex cannot stand for them)
  std::size_t hiddenComponentSplits = 0;  ///< adaptive: cells subdivided because a component of samples hides
                                          ///< inside them (criteria.h, hasHiddenComponent)
  std::size_t balanceSplits = 0;          ///< cells subdivided to restore 2:1 balance
};

/// @brief Builds the octree of one meta-cell.
/// @param[in] samples the meta-cell's dense samples (S + 3)^3.
/// @param[in] options construction, depths, criteria.
/// @param[out] stats optional figures of the construction.
/// @param[in] interrupter optional; checked once per depth.
/// @throw InputError for invalid options (see resolveDepths); Interrupted on cancellation.
LinearOctree buildOctree(const cell::MetaCellSamples& samples, const OctreeOptions& options = {},
                         OctreeBuildStats* stats = nullptr, Interrupter* interrupter = nullptr);

/// @brief True if no two leaves that share a face, an edge or a corner differ by more than one depth.
bool isBalanced(const LinearOctree& octree);

}  // namespace isovdb::octree
