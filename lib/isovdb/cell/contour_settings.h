// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file contour_settings.h
/// @brief The one place the contouring settings live.
///
/// The octree's construction, a meta-cell's contouring and the stitching of its
/// seams must read a cell the same way: the same isovalue, the same QEF, the
/// same reading of ambiguous faces. Each used to keep its own copy of these
/// fields, kept equal by comments. Now the pipeline fills one ContourSettings
/// and every stage reads it. Each stage keeps only its own knobs in its own
/// struct (octree::OctreeOptions: depths and refinement criteria).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "isovdb/named_values.h"

namespace isovdb::cell {

/// The contouring methods (`--method`).
enum class ContourMethod {
  Vdb,       ///< OpenVDB's tools::volumeToMesh, the reference (no octree)
  Regular,   ///< octree, every surface cell at the finest depth + manifold Dual Marching Cubes
  Adaptive,  ///< adaptive octree + dual contouring with Ju–Udeshi fans
};

inline constexpr NameTable<ContourMethod, 3> kContourMethodNames{
    {{ContourMethod::Vdb, "vdb"}, {ContourMethod::Regular, "regular"}, {ContourMethod::Adaptive, "adaptive"}}};
constexpr std::string_view contourMethodName(ContourMethod method) { return nameOf(kContourMethodNames, method); }
/// The method named `name`; std::nullopt for another name.
constexpr std::optional<ContourMethod> parseContourMethod(std::string_view name) {
  return valueNamed(kContourMethodNames, name);
}

/// How regular mode reads a cell with an ambiguous face or a body-diagonal contact.
enum class RegularTopology {
  Voxels,  ///< the voxel object's (26, 6) topology: joined faces, split doubled faces, tubes (contour/voxel_dmc)
  Mdmc,    ///< Wenger's Manifold DMC: faces separate the inside corners, doubled faces regrouped
};

inline constexpr NameTable<RegularTopology, 2> kRegularTopologyNames{
    {{RegularTopology::Voxels, "voxels"}, {RegularTopology::Mdmc, "mdmc"}}};
constexpr std::string_view regularTopologyName(RegularTopology topology) {
  return nameOf(kRegularTopologyNames, topology);
}
/// The reading named `name`; std::nullopt for another name.
constexpr std::optional<RegularTopology> parseRegularTopology(std::string_view name) {
  return valueNamed(kRegularTopologyNames, name);
}

/// An inclusive box of global index coordinates: {min, max}.
using DataBox = std::array<std::array<int, 3>, 2>;

/// What the octree, the contouring and the stitching of one field share.
struct ContourSettings {
  ContourMethod method = ContourMethod::Adaptive;
  /// Isovalue: inside iff value <= iso on distance fields (voxels; 0 = the surface).
  /// The engine flips a scalar field so that this holds there too.
  float iso = 0.0f;
  /// QEF truncation, relative to the largest singular value: higher = smoother
  /// vertices, lower = sharper features but less stable ones.
  float singularValueThreshold = 0.1f;
  /// Adaptive, exact distance fields: crossings beside a crease from the face they
  /// lie on and rim leaves refined (cell/crease_crossing.h, octree/surface_gap.h).
  bool sharpFeatures = false;
  /// Wenger's fix on doubled ambiguous faces (regular voxels: split doubled faces);
  /// off only in tests that show it matters.
  bool manifoldFix = true;
  /// Ju–Udeshi fans where the plain triangulation would leave its edge's envelope: adaptive
  /// mode, regular mode in Wenger's reading, and in the voxel reading (its polygons of more
  /// than four corners always fanned from the edge point, contour/voxel_dmc.h); off = plain
  /// dual contouring (regular: the better diagonal, polygons fanned from a corner), for comparison.
  bool intersectionFree = true;
  /// Regular: the reading of ambiguous cells.
  RegularTopology topology = RegularTopology::Voxels;
  /// The sampled data's box (the outermost samples), when the data have one. Outside it
  /// reads as outside, so a surface that leaves the data is closed by a cap beyond the
  /// face. Adaptive mode makes that cap while contouring: samples beyond the box read as
  /// far outside (pipeline/octree_contour.cc), leaves across a face are refined to one
  /// voxel (octree/build.cc) and their vertices kept within 2 * kInteriorMargin of it
  /// (contour/box_caps.h), so Ju–Udeshi's test sees the cap's final positions.
  /// Regular mode in Wenger's reading does the same (contoursByMinimalEdges); the voxel
  /// reading where the background lies inside the surface (a numpy field 40 - r at iso 0)
  /// too, else the background beyond the array would close a box around it.
  std::optional<DataBox> dataBox{};
  /// The sampled box where regular mode makes its caps on the field as it is (the voxel
  /// reading's mask distance fields, outside beyond the box; plain dual contouring with
  /// intersectionFree off): the vertices of the cells just beyond a face sit at their
  /// crossings' mass point, within 2 * kInteriorMargin of the face, and the edges that
  /// leave the box have their edge point there too (contour/box_caps.h). Nothing moves
  /// after the polygons' envelope tests.
  std::optional<DataBox> capBox{};

  /// Adaptive mode reads the cells where the voxel reading and MDMC's differ
  /// (cell::voxelReadingDiffers) as regular mode does on masks (adaptiveReadsVoxels).
  bool adaptiveVoxelReading = false;
  /// Adaptive mode with adaptiveVoxelReading: its mesh has the voxel object's topology.
  /// Those cells and their neighbours stay one voxel (octree/build.cc), and the edges of
  /// those cells get the voxel reading's polygons (contour/adaptive_contour.cc). Set for
  /// masks whose finest leaves are one voxel (pipeline/extract.cc).
  constexpr bool adaptiveReadsVoxels() const noexcept {
    return method == ContourMethod::Adaptive && adaptiveVoxelReading;
  }

  /// Contoured by minimal edges with Ju–Udeshi fans (contour/adaptive_contour.h): adaptive
  /// mode, and regular mode in Wenger's reading (fields) unless intersectionFree is off.
  /// There regular mode's tree (every surface cell at the finest depth) is contoured like an
  /// adaptive one: its quads between dual vertices near their cells' faces crossed each
  /// other (a level-set sphere: 234 self-intersecting pairs), the fans keep them apart.
  /// The voxel reading (masks) keeps its own polygons: tubes and split faces
  /// (contour/regular_contour.h).
  constexpr bool contoursByMinimalEdges() const noexcept {
    return method == ContourMethod::Adaptive ||
           (method == ContourMethod::Regular && topology == RegularTopology::Mdmc && intersectionFree);
  }
};

}  // namespace isovdb::cell
