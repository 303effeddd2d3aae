// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file box_rim_gradients.h
/// @brief The Prewitt gradients of the samples on the faces of the data's box, as the
///        field gave them, kept before the samples beyond the box read far outside.
///
/// Where the contouring makes its caps on the box's faces (ContourSettings::dataBox: adaptive
/// mode, regular mode in Wenger's reading), the samples beyond the box are overwritten as far
/// outside (pipeline/octree_contour.cc), so that an edge leaving the box crosses at its face.
/// A Prewitt stencil at a sample on a face reads the samples beyond it: overwritten, they made
/// every normal there point straight out of the box, and a vertex inside the box left the
/// QEF's minimiser that regular mode's voxel reading, which keeps the field as it is, finds
/// there. On a 2 x 2 column of a mask ending one voxel from the box, adaptive mode's vertex lay
/// 0.84 voxel from regular mode's, whatever the error bound. The gradients kept here are the
/// field's own: the cells inside the box see the same normals in every mode.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "isovdb/vec3.h"

namespace isovdb::cell {

/// Per face of the data's box that lies inside a meta-cell's block (with samples beyond it),
/// the gradients of the samples on it that lie inside the box. Offsets are the block's.
struct BoxRimGradients {
  bool active = false;                  ///< false: nothing kept (no face in the block, or no box)
  std::array<int, 3> first{0, 0, 0};    ///< the box's first sample offset along each axis
  std::array<int, 3> last{-1, -1, -1};  ///< and its last
  std::array<bool, 6> kept{};           ///< face 2 a + side (0: at first, 1: at last) kept
  int stride = 0;                       ///< the block's samples per axis
  int apron = 0;                        ///< the block's apron
  /// Per kept face, stride^2 gradients indexed by the two other axes' offsets (cyclic order).
  std::array<std::vector<Vec3f>, 6> faces;

  /// The kept gradient at offset (i, j, k), or nullptr where none is: off the box's faces,
  /// or beyond the box (those samples keep their far-outside stencil).
  const Vec3f* find(int i, int j, int k) const noexcept {
    const std::array<int, 3> p{i, j, k};
    for (std::size_t a = 0; a < 3; ++a)
      if (p[a] < first[a] || p[a] > last[a]) return nullptr;
    for (int a = 0; a < 3; ++a)
      for (int side = 0; side < 2; ++side) {
        const auto f = static_cast<std::size_t>(2 * a + side);
        if (kept[f] && p[static_cast<std::size_t>(a)] == (side ? last : first)[static_cast<std::size_t>(a)])
          return &faces[f][slot(p, a)];
      }
    return nullptr;
  }

  /// Index of offset p in the face array of axis a.
  std::size_t slot(const std::array<int, 3>& p, int a) const noexcept {
    const auto u = static_cast<std::size_t>((a + 1) % 3), v = static_cast<std::size_t>((a + 2) % 3);
    return static_cast<std::size_t>(p[v] + apron) * static_cast<std::size_t>(stride) +
           static_cast<std::size_t>(p[u] + apron);
  }
};

}  // namespace isovdb::cell
