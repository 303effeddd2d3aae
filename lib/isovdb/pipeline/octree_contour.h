// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file octree_contour.h
/// @brief Our own contouring methods on a distance field: the field cut into
///        meta-cells, each contoured with its own octree (regular: manifold DMC;
///        adaptive: DC + Ju–Udeshi), in parallel, and the seams between them
///        closed by edge-octree stitching (paper 000, sections 4.1–4.3).
///
/// Per meta-cell (one TBB pipeline token each; `--threads 1` = one meta-cell in
/// memory): read its (S + 1 + 2A)^3 samples, build the octree, contour the
/// edges inside it, hand the mesh to the sink in meta-cell order (so output
/// bytes do not depend on the thread count) and keep only the boundary cells
/// (contour/seam_cell.h). Then stitch/ contours the seams. Memory: the field,
/// one meta-cell's working set per token, and the kept cells; the mesh itself
/// goes to the sink (a file, when streaming).
///
/// `metaCellSize` 0 keeps the single-block path: one padded meta-cell around the
/// whole band, no seams (a dense block of the band's size; for comparison).
#pragma once

#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/mesh/mesh_sink.h"
#include "isovdb/octree/build.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

enum class OctreeMethod {
  Regular,   ///< regular construction + manifold Dual Marching Cubes: closed, manifold
  Adaptive,  ///< adaptive construction + dual contouring with Ju–Udeshi fans: closed, no self-intersection
};

struct OctreeContourOptions {
  OctreeMethod method = OctreeMethod::Regular;
  float iso = 0.f;         ///< isovalue (voxels on distance fields)
  int metaCellSize = 128;  ///< S, voxels per meta-cell edge (power of two, 16..512; 128 = VDB level-1 nodes);
                           ///< 0 = one meta-cell around the whole band (no stitching)
  int minLevel = -1;       ///< uniform subdivision down to this depth under the meta-cell; -1: maxCellSize decides
  int maxCellSize = 16;    ///< largest leaf in voxels when minLevel is -1 (coarser cells miss smooth detail:
                           ///< the QEF residual hardly grows on cells with few crossings)
  int maxLevel = -1;       ///< deepest level under the meta-cell; -1: finestCellSize decides
  int finestCellSize = 1;  ///< smallest leaf in voxels (power of two) when maxLevel is -1
  /// adaptive: split leaves whose QEF residual (RMS voxels) exceeds it; <0 off. 0.15: on the
  /// interface distance field of a mask, as close to analytic solids as 0.25 was on
  /// topologyToLevelSet's noisier field, with as many vertices (bench/field_accuracy.py).
  float qefTolerance = 0.15f;
  /// Regular: how ambiguous cells are read. Voxels (default) keeps the voxel object's topology
  /// (26-connected inside, 6-connected outside: chi(mesh) = 2 chi(object) on masks); Mdmc is
  /// Wenger's Manifold DMC (inside corners of ambiguous faces separated; adaptive mode's reading).
  contour::RegularTopology regularTopology = contour::RegularTopology::Voxels;
  bool manifoldFix = true;       ///< Wenger's fix, both methods (regular voxels: split doubled faces); tests
                                 ///< switch it off to show it matters
  bool intersectionFree = true;  ///< adaptive: Ju–Udeshi fans (false: plain DC, for comparison)
  bool sharpFeatures = false;    ///< adaptive, exact distance fields: keep sharp edges and corners (crossings
                                 ///< near a crease from their own face, leaves refined until their vertex is
                                 ///< on the zero level: octree::OctreeOptions::sharpFeatures). Off by default:
                                 ///< a field made from a voxel mask has a crease at every step of its
                                 ///< staircase (salt body: 1.5x the triangles)
};

/// Contours a DistanceField (inside = value <= iso) or a Scalar volume (inside =
/// value >= iso) with our octree methods into `sink` (voxel index space,
/// outward-oriented triangles).
/// @throw InputError for a mask volume, an invalid meta-cell size or invalid levels;
///        Interrupted on cancellation.
void contourWithOctree(const volume::Volume& field, const OctreeContourOptions& options, mesh::MeshSink& sink,
                       Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// The same, collected into a mesh.
mesh::Mesh contourWithOctree(const volume::Volume& field, const OctreeContourOptions& options,
                             Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

}  // namespace isovdb::pipeline
