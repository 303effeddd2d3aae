// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file extract.h
/// @brief The main job: a loaded volume → distance field → contour → mesh in world space.
///
/// This is the only place that knows the order of the stages (DESIGN.md, data flow).
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <string_view>

#include "isovdb/mesh/mesh.h"
#include "isovdb/named_values.h"
#include "isovdb/mesh/mesh_sink.h"
#include "isovdb/pipeline/data_boundary.h"
#include "isovdb/pipeline/octree_contour.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

using cell::ContourMethod;
using cell::contourMethodName;
using cell::parseContourMethod;
using cell::parseRegularTopology;

/// The reading ExtractOptions::regularTopology gives for an input of `kind`.
cell::RegularTopology regularTopologyFor(const std::optional<cell::RegularTopology>& chosen, volume::VolumeKind kind);

/// Adaptive mode's default error bound (voxels, `--max-error`). One voxel keeps what
/// adaptive mode is for (salt dome at 512^3: 19 % more triangles than without a bound,
/// still 8x fewer than regular mode; the rough blobs: 1.8x more, 2.3x fewer than regular)
/// and the mesh within a voxel of the full-resolution surface; below half a voxel a mask's
/// one-voxel steps refine most leaves to one voxel (docs/cli.md, the error bound's table).
inline constexpr float kDefaultMaxError = 1.0f;

/// Which side of the isovalue a scalar field's object lies on: above (density, CT,
/// amplitude: inside = value > iso) or below (a signed distance negative inside, as
/// OpenVDB's level sets and scikit-fmm's fields; a travel time). Masks and distance fields
/// have their own sides (the mask's voxels; negative inside).
enum class ScalarInside { Above, Below };
inline constexpr NameTable<ScalarInside, 2> kScalarInsideNames{
    {{ScalarInside::Above, "above"}, {ScalarInside::Below, "below"}}};

/// Every setting of `isovdb extract` (each field is a CLI flag and a Python keyword).
struct ExtractOptions {
  /// The method (adaptive by default, the CLI's and Python's: our engine within
  /// kDefaultMaxError; vdb is OpenVDB's volumeToMesh, the reference) and what the octree, contouring and
  /// stitching share. Its iso is set from `iso` (isoFor).
  cell::ContourSettings contour{.method = ContourMethod::Adaptive};
  /// The isovalue: voxels on a distance field (0 = the mask boundary, > 0 grows the surface), the field's units on a
  /// scalar volume. Unset: 0 on masks and distance fields, the middle of a scalar field's values (isoFor).
  std::optional<float> iso;
  /// Octree methods: the octree's own knobs (depths, QEF, error bound and feature criteria).
  octree::OctreeOptions octree{.maxError = kDefaultMaxError};
  /// Octree methods: S, voxels per meta-cell edge (power of two, 16..512; 128 = VDB
  /// level-1 nodes); 0 = one meta-cell around the whole band (no stitching).
  int metaCellSize = 128;
  /// `vdb` method only: OpenVDB's adaptivity in [0, 1].
  double adaptivity = 0.0;
  /// Used when the input is a mask.
  volume::DistanceFieldOptions distance;
  /// `regular` method: reading of ambiguous cells; unset = Voxels when the input is a
  /// binary mask (the mesh then has the mask's topology), Mdmc on fields (distance
  /// fields, scalars, reconstructions), where no voxel object defines one. Sets
  /// contour.topology.
  std::optional<cell::RegularTopology> regularTopology;
  /// Worker threads for the whole job (TBB); 0 = every core. The output does not depend on it.
  int threads = 0;
  /// Surfaces reaching the sampled data's boundary: capped there (closed mesh) or
  /// left open on it (data_boundary.h). Volumes without a sampled box are left as contoured.
  BoundaryMode boundary = BoundaryMode::Cap;
  /// Scalar fields: the object's side of the isovalue (ignored for masks and distance fields).
  ScalarInside scalarInside = ScalarInside::Above;
};

/// The isovalue `options` contour `volume` at: options.iso, or when unset 0 on masks and distance
/// fields and the middle of a scalar field's values (scikit-image's rule); the background counts
/// where it stands for samples (inactive voxels inside the sampled box, or a grid without one).
/// @throw InputError for a scalar field whose values are all equal (it has no middle).
float isoFor(const volume::Volume& volume, const ExtractOptions& options);

/// A scalar field whose inside lies below the isovalue becomes -field, and `iso` -iso: the
/// engine and volumeToMesh take a scalar's inside above it. A copy (volume::negatedScalar),
/// so the caller's volume is unchanged; any other input is returned as it is.
volume::Volume withInsideAboveIso(const volume::Volume& volume, ScalarInside inside, float& iso);

/// A mask becomes its distance field; distance fields and scalars pass through.
volume::Volume toContourable(const volume::Volume& volume, const volume::DistanceFieldOptions& options,
                             Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// How extractInto takes part in an extraction split over processes (isovdb.distributed,
/// pipeline/meta_cell_pieces.h). A task reads one slab of meta-cell layers (plus the halo
/// its distance field needs, slabHalo) and hands the meta-cells of `layers` to `pieces`:
/// nothing reaches the sink and nothing is stitched. The client reads only the file's
/// header (an empty window), contours nothing, and takes every meta-cell from `received`
/// in meta-cell order, assembling and stitching them into the sink as one process does
/// its own: the same bytes as `isovdb extract` with the same settings.
struct ExtractPart {
  std::optional<MetaCellLayers> layers;  ///< task: the slab it contours
  MetaCellConsumer* pieces = nullptr;    ///< task: where its meta-cells go
  /// Client: the next meta-cell of the run, in meta-cell order; false after the last.
  std::function<bool(volume::MetaCellIndex&, contour::MetaCellMesh&)> received;
  /// Fields (scalar, distance), task and client alike: the whole volume's value range
  /// (valueRangeOf the slabs' SampleRanges), which neither holds: the default iso, the
  /// iso's check and the far-outside value beyond the box derive from it.
  std::optional<std::pair<float, float>> valueRange;
};

/// What a field's value range is made of: its active samples' count and extremes (within
/// a slab, for a distributed run's first pass) and its background.
struct SampleRange {
  std::int64_t active = 0;
  float min = 0.f, max = 0.f;
  float background = 0.f;
  /// Both slabs' samples (backgrounds are the same file's).
  SampleRange& operator+=(const SampleRange& other);
};
SampleRange sampleRangeOf(const volume::Volume& field);

/// A scalar field's value range from its samples' SampleRange (summed over every slab):
/// the active samples' extremes, and the background where inactive samples lie inside
/// the sampled `box` (or there is no box), as isoFor reads a whole volume.
std::pair<float, float> valueRangeOf(const SampleRange& samples, const std::optional<volume::IndexBox>& box);

/// Samples beyond its layers a task must read so that its meta-cells' samples are the
/// whole volume's: the meta-cells' apron, the distance field's reach (half-width, blur,
/// closing) and the band's leaf margins, rounded up to whole 8-voxel leaves.
int slabHalo(const ExtractOptions& options);

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
/// `part`: one side of a distributed run (see ExtractPart).
void extractInto(volume::Volume volume, const ExtractOptions& options, mesh::MeshSink& sink,
                 Interrupter* interrupter = nullptr, Statistics* stats = nullptr, const ExtractPart* part = nullptr);

/// world = origin + spacing * index, applied in place (flips nothing: spacings are positive).
void indexToWorld(mesh::Mesh& mesh, const volume::Geometry& geometry);

}  // namespace isovdb::pipeline
