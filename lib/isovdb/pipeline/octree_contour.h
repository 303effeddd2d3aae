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
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

/// Contours a DistanceField (inside = value <= iso) or a Scalar volume (inside =
/// value >= iso) with our octree methods into `sink` (voxel index space,
/// outward-oriented triangles).
/// @throw InputError for a mask volume, an invalid meta-cell size or invalid levels;
///        Interrupted on cancellation.
/// `settings` (method Regular or Adaptive) are read by the octree, the contouring and
/// the stitching alike; `tree` holds the octree's own knobs; `metaCellSize` is S, a
/// power of two in 16..512 (128 = VDB level-1 nodes), or 0 for one padded block
/// around the whole band (no stitching).
void contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                       const octree::OctreeOptions& tree, int metaCellSize, mesh::MeshSink& sink,
                       Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// Contours a Mask volume in meta-cells of `metaCellSize` (16..512), its distance
/// field (`distance`: the Interface method) computed one layer of meta-cells at a
/// time just before they are contoured (volume/slab_band.h), so the whole band is
/// never held: the mask, a few layers of band and one meta-cell per token. The
/// same bytes as contourWithOctree(distanceField(mask, distance), ...). Records the
/// "distance_field" statistics too.
/// @throw InputError for another kind, the tracker method, an invalid meta-cell size;
///        Interrupted on cancellation.
void contourMaskWithOctree(const volume::Volume& mask, const volume::DistanceFieldOptions& distance,
                           const cell::ContourSettings& settings, const octree::OctreeOptions& tree, int metaCellSize,
                           mesh::MeshSink& sink, Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// The same, collected into a mesh.
mesh::Mesh contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                             const octree::OctreeOptions& tree = {}, int metaCellSize = 128,
                             Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// The octree contourWithOctree builds for meta-cell `index` of `field`: the same
/// samples, apron and isovalue (negated on a scalar field), for `isovdb octree`.
/// `hasSignChange` (optional) says whether the meta-cell's samples cross the surface.
octree::LinearOctree metaCellOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                                    const octree::OctreeOptions& tree, int metaCellSize,
                                    const std::array<int, 3>& index, octree::OctreeBuildStats* stats = nullptr,
                                    bool* hasSignChange = nullptr, Interrupter* interrupter = nullptr);

}  // namespace isovdb::pipeline
