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
///   one depth); optionally geometric criteria (QEF error above a tolerance;
///   the full-resolution surface farther than the error bound from the vertex's
///   plane; with sharp features, a vertex off a curved crease) refine further. For octree dual contouring + Ju–Udeshi.
/// Memory: O(leaves) beside the dense cell::MetaCellSamples block. Deterministic:
/// the result does not depend on the number of threads.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "isovdb/octree/linear_octree.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/cell/contour_settings.h"
#include "isovdb/progress.h"

namespace isovdb::octree {

class UnitEdgeCrossings;  // unit_edge_crossings.h
class SamplePhases;       // sample_phases.h

/// What the error bound keeps in hand (voxels): the mesh is held to maxError less this where
/// it is checked from samples (contour/error_bound.h: mesh points against the level set to
/// first order, regular mode's vertices but not its triangles) and on the seam, which only
/// the tree's own criterion sees (it is stitched later). Between the samples,
/// and where regular mode's mesh leaves the level set, up to 0.05 voxel went unseen: 48^3 and
/// 64^3 blobs masks ended up to 0.30 voxel from regular mode's mesh at E = 0.25, a 300^3 torus
/// 0.28 across a seam; with 1/16 voxel in hand one of 24 masks still ended 0.2503 away.
inline constexpr float kErrorBoundMargin = 0.1f;

/// With an error bound E, leaves are held to the QEF tolerance or to this share of E,
/// whichever is larger. Inside the meta-cell the bound's check after contouring holds the
/// leaves, so there the QEF criterion only saves check passes (each rebuilds the block); on
/// its boundary the plane test (kPlaneShare) and this share hold them. At 0.45 (E = 1),
/// 256^3: salt 18 % and gyroid 27 % fewer triangles inside the meta-cells, blobs one pass (no
/// QEF criterion there: 10 passes; a share of 0.6 took 3 at E = 0.5); on the boundaries too,
/// salt 6 % and gyroid 4 % fewer. The share holds with the QEF criterion turned off as well:
/// with none (--qef-tolerance -1, before) a one-voxel-thin structure on a seam of the 256^3
/// blobs ended 1.11 voxels from regular mode's mesh at E = 1, which the plane test let pass.
inline constexpr float kBoundedQefShare = 0.45f;

/// The share of the error bound E the full-resolution surface may stray from a leaf's vertex
/// plane (octree/surface_deviation.h) on the seam, a leaf whose face on the meta-cell's
/// boundary the surface crosses (crossesMetaCellBoundary; a leaf of four voxels or more that
/// only touches the boundary has no seam triangles, and the check holds it as inside; one of
/// two voxels keeps this share): the mesh around the vertex
/// is not that plane but triangles to the neighbours' vertices, each off by as much in its own
/// cell (a share of 1 let a one-voxel bump under a leaf end 1.27 voxels from the adaptive mesh
/// at E = 1). There the check does not hold the bound: the seams are stitched unchecked
/// (beside kBoundedQefShare, this share holds them). Leaves of two voxels inside the
/// meta-cell take the larger of this share and E less kTwoVoxelReserve.
inline constexpr float kPlaneShare = 0.5f;

/// What leaves of two voxels inside the meta-cell keep in hand from E (voxels) for what the
/// check's samples do not see at their scale: there regular mode's quads and the adaptive
/// mesh's Ju-Udeshi fans differ by a few tenths of a voxel whatever E is. With the whole of E,
/// or 0.75 E, a fan lay 0.30 voxel from regular mode's quad at E = 0.25 (96^3 blobs; its
/// vertices and the mesh's points against the level set all held); with E less
/// kErrorBoundMargin, what the check itself allows, a 64^3 blobs mask ended 0.265 away. Only
/// E > 0.5 gains from it: at E = 1 the leaves take 0.75 voxel instead of 0.5, and the 256^3
/// blobs need 26 % fewer triangles, the gyroid 16 %, the frog 7 %.
inline constexpr float kTwoVoxelReserve = 0.25f;

/// The same share for leaves of four voxels or more inside the meta-cell, which the bound's
/// check after contouring covers: there the plane test only saves check passes. At 1 (E = 1,
/// 256^3): salt 37 % and gyroid 13 % fewer triangles than at kPlaneShare, in 2 and 5 passes.
inline constexpr float kInteriorPlaneShare = 1.0f;

/// The octree's own knobs: depths and refinement criteria. The method (regular:
/// every surface cell at the maximum depth; adaptive: complex cells refined, 2:1
/// balanced), the isovalue, the QEF truncation and sharp features come from the
/// cell::ContourSettings that the contouring reads too. Depths count from the
/// meta-cell root (0); a depth d has cells of S >> d voxels. The defaults are
/// `isovdb extract`'s.
struct OctreeOptions {
  int minDepth = -1;       ///< uniform subdivision down to this depth (CLI --min-level); -1: maxCellSize decides
  int maxDepth = -1;       ///< deepest depth (CLI --max-level); -1: finestCellSize decides (1-voxel cells if 0)
  int maxCellSize = 16;    ///< largest leaf in voxels (power of two, clamped to the meta-cell) when minDepth is -1:
                           ///< coarser cells miss smooth detail (the QEF residual hardly grows with few crossings)
  int finestCellSize = 1;  ///< smallest leaf in voxels (power of two) when maxDepth is -1
  /// Adaptive: also split a surface leaf whose dual vertex is farther than this RMS
  /// distance (voxels) from its tangent planes; < 0 off. 0.15: on the interface
  /// distance field of a mask, as close to analytic solids as 0.25 was on
  /// topologyToLevelSet's noisier field, with as many vertices (bench/field_accuracy.py).
  /// With maxError > 0, at least kBoundedQefShare * maxError (also when < 0 here).
  float qefTolerance = 0.15f;
  /// Adaptive with sharp features: also split a surface leaf whose crossing normals are
  /// more than 60 degrees apart and whose dual vertex is at least this far (voxels) off
  /// the zero level by the field's Lipschitz bound (surface_gap.h): on a curved rim the
  /// tangent planes of a coarse leaf meet outside the rim, with an almost exact fit.
  float featureTolerance = 0.05f;
  /// Adaptive: also split a surface leaf where the full-resolution surface strays
  /// farther than this (voxels) from the plane of its dual vertex (surface_deviation.h):
  /// the adaptive mesh then stays within about this distance of the regular mesh; <= 0 off.
  float maxError = -1.0f;
  /// Cells split whatever the criteria say (sorted Morton keys): where the mesh of an
  /// earlier pass broke the error bound (contour/error_bound.h).
  std::vector<MortonKey> forcedSplits{};
  bool detectInteriorComponents = true;  ///< a cell with one-phase faces but a sample of the other phase inside
                                         ///< is complex (catches blobs that touch no face; one pass over such cells)
  bool parallel = true;                  ///< evaluate each level's cells with TBB (the result is the same)
};

/// Depths after resolving cell sizes against the meta-cell size.
struct OctreeDepths {
  int minDepth = 0;
  int maxDepth = 0;
};

/// @brief Resolves depths and cell sizes of `options` for a meta-cell of `metaCellSize` voxels:
///        a depth >= 0 wins over the matching cell size; maxCellSize is clamped to the meta-cell.
/// @throw InputError if a size is not a power of two <= metaCellSize or minDepth > maxDepth.
OctreeDepths resolveDepths(const OctreeOptions& options, int metaCellSize);

/// @brief Edge, in voxels, of the finest leaves `options` allow in a meta-cell of `metaCellSize` voxels.
/// @throw InputError as resolveDepths.
int finestLeafSize(const OctreeOptions& options, int metaCellSize);

/// What the construction did (figures for statistics and tests).
struct OctreeBuildStats {
  std::vector<std::size_t> cellsClassified;  ///< per depth: cells whose criteria were evaluated
  std::size_t complexEdges = 0;              ///< complex cell edges found (an edge shared by k cells counts k times)
  std::size_t complexFaces = 0;              ///< complex cell faces found (same)
  std::size_t interiorComponents = 0;        ///< cells complex only through an interior component
  std::size_t complexCells = 0;              ///< complex cells found (subdivided or left at the maximum depth)
  std::size_t unresolvedComplexLeaves = 0;   ///< complex leaves at the maximum depth
  std::size_t geometricSplits = 0;           ///< cells subdivided by a geometric criterion (QEF, error bound)
  std::size_t featureSplits = 0;             ///< of them, by the sharp-feature gap (OctreeOptions::sharpFeatures)
  std::size_t errorBoundSplits = 0;          ///< of them, by the error bound (OctreeOptions::maxError)
  std::size_t dataBoxSplits = 0;     ///< adaptive: cells subdivided because they lie across a face of the data's box
  std::size_t multiSheetSplits = 0;  ///< adaptive: cells subdivided because their configuration has several
                                     ///< DMC groups or a doubled ambiguous face (one vertex cannot stand for them)
  std::size_t hiddenComponentSplits = 0;  ///< adaptive: cells subdivided because a component of samples hides
                                          ///< inside them (criteria.h, hasHiddenComponent)
  std::size_t balanceSplits = 0;          ///< cells subdivided to restore 2:1 balance

  /// Sums the figures of several meta-cells (cellsClassified depth by depth).
  OctreeBuildStats& operator+=(const OctreeBuildStats& o);
};

/// What one build of a block's octree evaluated, handed to the next build of the same block
/// (the error bound's passes build it again with a few more forced splits). Every other
/// cell's evaluation is a function of the samples and the options, so the next build recalls
/// it instead of classifying the cell and placing its vertex again. About 80 bytes per cell
/// evaluated coarser than a voxel (unit cells are not kept: cheap to evaluate, and most of a
/// mask's cells); keep one per block, for that block's passes only.
class BuildMemo {
 public:
  BuildMemo();
  ~BuildMemo();
  BuildMemo(const BuildMemo&) = delete;
  BuildMemo& operator=(const BuildMemo&) = delete;

  struct Impl;  // build.cc
  Impl& impl() noexcept { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

/// @brief Builds the octree of one meta-cell.
/// @param[in] samples the meta-cell's dense samples (S + 3)^3.
/// @param[in] settings the method (Regular or Adaptive), isovalue, QEF truncation and
///            sharp features, as the contouring will read them.
/// @param[in] options depths and refinement criteria.
/// @param[out] stats optional figures of the construction.
/// @param[in] interrupter optional; checked once per depth.
/// @param[in] crossings optional: the samples' unit-edge crossings at settings.iso (with
///            settings.sharpFeatures), which the cells' dual vertices then read; the
///            same tree.
/// @param[in] phases optional: the samples' phases at settings.iso (computed here without them).
/// @param[in,out] memo optional: what earlier builds of these samples with these settings and
///            options (forced splits aside) evaluated; this build's evaluations are added.
/// @throw InputError for invalid options (see resolveDepths) or the Vdb method;
///        Interrupted on cancellation.
LinearOctree buildOctree(const cell::MetaCellSamples& samples, const cell::ContourSettings& settings,
                         const OctreeOptions& options = {}, OctreeBuildStats* stats = nullptr,
                         Interrupter* interrupter = nullptr, const UnitEdgeCrossings* crossings = nullptr,
                         const SamplePhases* phases = nullptr, BuildMemo* memo = nullptr);

/// @brief True if no two leaves that share a face, an edge or a corner differ by more than one depth.
bool isBalanced(const LinearOctree& octree);

}  // namespace isovdb::octree
