// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file extract.h
/// @brief The main job: a loaded volume → distance field → contour → mesh in world space.
///
/// This is the only place that knows the order of the stages (DESIGN.md, data flow).
#pragma once

#include <optional>
#include <string_view>

#include "isovdb/mesh/mesh.h"
#include "isovdb/mesh/mesh_sink.h"
#include "isovdb/pipeline/data_boundary.h"
#include "isovdb/pipeline/octree_contour.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

/// Contouring methods. Our own octree methods (regular, adaptive) plug in here.
enum class ContourMethod {
  Vdb,       ///< OpenVDB tools::volumeToMesh, the reference
  Regular,   ///< octree, regular construction + manifold Dual Marching Cubes (closed, manifold)
  Adaptive,  ///< octree, adaptive construction + dual contouring with Ju–Udeshi fans
};

std::optional<ContourMethod> parseContourMethod(std::string_view name);
std::string_view contourMethodName(ContourMethod method);

/// Regular mode's reading of ambiguous cells by name: "voxels" or "mdmc".
std::optional<contour::RegularTopology> parseRegularTopology(std::string_view name);

/// The reading ExtractOptions::regularTopology gives for an input of `kind`.
contour::RegularTopology regularTopologyFor(const std::optional<contour::RegularTopology>& chosen,
                                            volume::VolumeKind kind);

struct ExtractOptions {
  ContourMethod method = ContourMethod::Vdb;
  /// Isovalue: in voxels on a distance field (0 = the mask boundary, >0 grows the
  /// surface outwards), in the field's units on a scalar volume.
  double iso = 0.0;
  /// `vdb` method only: OpenVDB's adaptivity in [0, 1].
  double adaptivity = 0.0;
  /// Used when the input is a mask.
  volume::DistanceFieldOptions distance;
  /// `regular` and `adaptive` methods (iso and method are taken from above).
  OctreeContourOptions octree;
  /// `regular` method: reading of ambiguous cells; unset = Voxels when the input is a
  /// binary mask (the mesh then has the mask's topology), Mdmc on fields (distance
  /// fields, scalars, reconstructions), where no voxel object defines one. Overrides
  /// octree.regularTopology.
  std::optional<contour::RegularTopology> regularTopology;
  /// Worker threads for the whole job (TBB); 0 = every core. The output does not depend on it.
  int threads = 0;
  /// Surfaces reaching the sampled data's boundary: capped there (closed mesh) or
  /// left open on it (data_boundary.h). Volumes without a sampled box are left as contoured.
  BoundaryMode boundary = BoundaryMode::Cap;
};

/// A mask becomes its distance field; distance fields and scalars pass through.
volume::Volume toContourable(const volume::Volume& volume, const volume::DistanceFieldOptions& options,
                             Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// Contours `volume` (any kind) and returns the mesh in world space
/// (Volume::geometry() applied), outward-oriented, with `options.boundary` applied
/// on the volume's sampled box. Records timings and counts in `stats`.
/// `volume` is taken by value (a copy shares the grid): a caller that moves its
/// mask in lets the pipeline free the mask once the distance field is made.
/// @throw InputError for invalid options, or an iso inside a scalar's dead band
///        (|iso| < clip: the surface would follow clipped samples); Interrupted on cancellation.
mesh::Mesh extractMesh(volume::Volume volume, const ExtractOptions& options, Interrupter* interrupter = nullptr,
                       Statistics* stats = nullptr);

/// The same, streamed into `sink` in voxel INDEX space (the octree methods hand
/// it one meta-cell at a time; apply volume.geometry() in the sink, e.g.
/// io::PlyStreamWriter's transform).
void extractInto(volume::Volume volume, const ExtractOptions& options, mesh::MeshSink& sink,
                 Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// world = origin + spacing * index, applied in place (flips nothing: spacings are positive).
void indexToWorld(mesh::Mesh& mesh, const volume::Geometry& geometry);

}  // namespace isovdb::pipeline
