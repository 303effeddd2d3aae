// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file criteria.h
/// @brief Topological subdivision criteria of an octree cell, evaluated on the
///        voxel samples of its edges and faces (paper 000, section 4.2.1, Fig. 4.3).
///
/// - An edge is *complex* if the inside/outside state changes more than once
///   along the samples on it.
/// - A face is *complex* if none of its edges is complex but a connected
///   component of its samples (4-connectivity) touches none of its four edges.
///   Both phases are labelled: an inside island and an outside hole (e.g. the
///   hole of a ring) are both closed contour loops that the edges cannot see.
///   (The paper labels inside samples only, with Hoshen–Kopelman; labelling
///   both is a superset and never misses a hole.)
/// - A cell is complex if one of its edges or faces is complex. Optionally
///   (CellClassifyOptions::detectInteriorComponents) a cell whose six faces are
///   all one phase but which holds a sample of the other phase (a blob or
///   bubble touching no face) is complex too, so no component is lost.
///
/// Sign convention: inside iff value <= iso. Coordinates are offsets in the
/// meta-cell (voxel index space minus cell::MetaCellSamples::origin). The criteria
/// read the samples' phases only (sample_phases.h), never their values.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/octree/morton.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

/// @brief Number of inside/outside transitions between consecutive samples of
///        the axis-aligned segment from `start` to `start + length * e_axis`.
/// @pre the segment lies in [-1, S + 1]^3.
int countSignChanges(const SamplePhases& phases, std::array<int, 3> start, int axis, int length) noexcept;

/// @brief True iff the edge is complex (more than one sign change along its samples).
inline bool isComplexEdge(const SamplePhases& phases, std::array<int, 3> start, int axis, int length) noexcept {
  return countSignChanges(phases, start, axis, length) > 1;
}

/// @brief Finds the components of a square face of samples that touch none of
///        its edges: a bit-parallel flood from the border for faces of at most
///        64 samples a side, Hoshen–Kopelman labelling for wider ones. Reusable
///        scratch buffers (one object per thread; no allocation once warmed up).
class FaceLabeller {
 public:
  /// What the labelling of one face found.
  struct Result {
    bool isolatedComponent = false;  ///< a component (either phase) touches none of the face's edges
    bool uniform = true;             ///< all samples of the face are one phase
    bool inside = false;             ///< phase of the first sample (the face's min corner)
  };

  /// @brief Labels the (size + 1)^2 samples of the face with min corner
  ///        `origin`, normal `normalAxis`, side length `size` (cells).
  /// @pre the face lies in [-1, S + 1]^3; size >= 1.
  Result label(const SamplePhases& phases, std::array<int, 3> origin, int normalAxis, int size);

 private:
  // Faces of at most 64 samples a side: one word per row, bit-parallel flood.
  std::vector<std::uint64_t> rows_, floodPhase_, floodReached_;
  // Wider faces: Hoshen–Kopelman labelling.
  std::vector<std::uint8_t> phase_;
  std::vector<std::int32_t> parent_;
  std::vector<std::uint8_t> touches_;
};

/// Options of classifyCell.
struct CellClassifyOptions {
  bool detectInteriorComponents = true;  ///< scan the interior of cells whose faces are all one phase
                                         ///< (costs one pass over those cells' samples)
};

/// @brief Topological classification of one cell.
struct CellTopology {
  std::uint8_t cornerSigns = 0;    ///< bit c set iff corner c is inside
  std::uint16_t complexEdges = 0;  ///< bit e set iff cell edge e is complex
  std::uint8_t complexFaces = 0;   ///< bit f set iff face f is complex (only evaluated when no edge is complex)
  bool boundaryUniform = false;    ///< all samples on the cell's faces are one phase
  bool interiorComponent = false;  ///< boundary uniform but an interior sample has the other phase
  bool facesEvaluated = false;     ///< faces were labelled (no complex edge)

  /// Complex cell: a complex edge, a complex face, or (if detected) an interior component.
  bool isComplex() const noexcept { return complexEdges != 0 || complexFaces != 0 || interiorComponent; }
  /// The surface crosses the cell (its samples are not all one phase).
  bool isHeterogeneous() const noexcept { return !boundaryUniform || interiorComponent; }
};

/// @brief Classifies the cell with min corner `origin` (meta-cell offsets) and side `size`.
/// @pre the cell lies in [0, S]^3.
CellTopology classifyCell(const SamplePhases& phases, std::array<int, 3> origin, int size,
                          const CellClassifyOptions& options, FaceLabeller& labeller);

/// @brief True if the cell [origin, origin + size] holds a connected set of
///        samples of one phase that touches none of its faces: a bubble or a
///        speck hidden inside a cell whose faces the surface does cross, which
///        the edge and face criteria cannot see (6-connectivity for both
///        phases, so a set joined to the faces only diagonally counts as hidden
///        too: a conservative answer that costs at most a split). O(size^3),
///        flood fill from the faces with per-thread scratch.
/// @pre the cell lies in [0, S]^3.
bool hasHiddenComponent(const SamplePhases& phases, std::array<int, 3> origin, int size);

/// @brief 8-bit corner sign configuration of a cell (bit c set iff corner c inside), read from
///        the phases (cell::cellCornerSigns reads the samples).
std::uint8_t cellCornerSigns(const SamplePhases& phases, std::array<int, 3> origin, int size) noexcept;

}  // namespace isovdb::octree
