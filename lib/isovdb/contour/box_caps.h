// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file box_caps.h
/// @brief Caps made while contouring where a surface leaves the data's box: the vertices
///        of cells just beyond a face are held within 2 * kInteriorMargin of it, and the
///        edges that leave the box get their edge point there too. Ju–Udeshi's envelope
///        tests then see the caps' final positions (nothing moves after them), and every
///        vertex stays strictly inside its cell, which the envelopes need.
///
/// Both octree modes use it: adaptive mode (and regular mode in Wenger's reading) on
/// samples that read far outside beyond the box (cell::ContourSettings::dataBox), regular
/// mode's voxel reading on the mask's own distance field (ContourSettings::capBox).
#pragma once

#include <array>

#include "isovdb/cell/contour_settings.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/vec3.h"

namespace isovdb::contour {

/// @brief A vertex `p` of `leaf` (global coordinates; `treeOrigin` = global coordinate of
///        the tree's offset 0) moved, on each axis where the leaf lies just beyond a face of
///        `box`, to within 2 * kInteriorMargin * size of that face (the float nearest that
///        point on the leaf's side, so that it stays beyond the face once stored as a float).
Vec3d besideDataBox(Vec3d p, const octree::OctreeLeaf& leaf, const std::array<int, 3>& treeOrigin,
                    const cell::DataBox& box);

/// @brief The edge point of the edge from `start` along `axis` (length `size`), as an
///        offset `t` from its start: if the edge leaves `box` through a face, the point
///        `margin` from that face (on the edge, beyond it), where the cap lies; else `t`.
float edgePointBesideDataBox(float t, const std::array<int, 3>& start, int axis, int size, float margin,
                             const cell::DataBox& box);

}  // namespace isovdb::contour
