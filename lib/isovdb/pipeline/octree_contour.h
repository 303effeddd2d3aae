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

#include <optional>

#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/mesh/mesh_sink.h"
#include "isovdb/octree/build.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/stitch/stitch_seams.h"
#include "isovdb/volume/meta_cells.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

/// Meta-cell layers [begin, end) along z (layer k: meta-cells with z from k S to k S + S):
/// the part of a run one task of a distributed run contours (isovdb.distributed).
struct MetaCellLayers {
  int begin = 0;
  int end = 0;
  bool contains(int k) const noexcept { return begin <= k && k < end; }
};

/// Where contoured meta-cells go, one at a time, in meta-cell order (z, y, x).
class MetaCellConsumer {
 public:
  virtual ~MetaCellConsumer() = default;
  /// Meta-cell `index`'s mesh (global voxel index coordinates, ids local to it) and seam.
  virtual void add(const volume::MetaCellIndex& index, contour::MetaCellMesh&& block) = 0;
};

/// Appends each meta-cell's mesh to a sink, its ids moved after the vertices already
/// there, and hands its seam to the stitcher (which stitches each layer's seams once the
/// next layer is complete); finish() appends the stitched mesh to the sink. What one process
/// does with its meta-cells, and what a distributed run's client does with the pieces its
/// tasks return: the same calls in the same order, so the same bytes.
class SeamedMeshAssembler final : public MetaCellConsumer {
 public:
  SeamedMeshAssembler(const cell::ContourSettings& settings, int metaCellSize, mesh::MeshSink& sink)
      : sink_(sink), stitcher_(settings, metaCellSize) {}
  void add(const volume::MetaCellIndex& index, contour::MetaCellMesh&& block) override;
  /// Stitches every seam kept (stage "stitch"; figures under "stitch").
  void finish(Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

 private:
  mesh::MeshSink& sink_;
  stitch::SeamStitcher stitcher_;  ///< stitches as layers complete; its mesh goes last
};

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

/// contourWithOctree and contourMaskWithOctree for one part of a distributed run: only
/// the meta-cells of `layers` (all when unset) are contoured and handed to `consumer`;
/// nothing is stitched. `metaCellSize` 16..512. `valueBound` (scalar fields): the largest
/// |value| of the whole volume, when `field` holds only a slab of it (the caps' far
/// outside value derives from it; blocks must agree on it).
void contourMetaCellsInto(const volume::Volume& field, const cell::ContourSettings& settings,
                          const octree::OctreeOptions& tree, int metaCellSize, MetaCellConsumer& consumer,
                          const std::optional<MetaCellLayers>& layers, std::optional<float> valueBound = std::nullopt,
                          Interrupter* interrupter = nullptr, Statistics* stats = nullptr);
void contourMaskMetaCellsInto(const volume::Volume& mask, const volume::DistanceFieldOptions& distance,
                              const cell::ContourSettings& settings, const octree::OctreeOptions& tree,
                              int metaCellSize, MetaCellConsumer& consumer, const std::optional<MetaCellLayers>& layers,
                              Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

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
