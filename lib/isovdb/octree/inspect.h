// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file inspect.h
/// @brief Figures and a wireframe of an octree, for statistics, tests and debugging.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "isovdb/octree/build.h"
#include "isovdb/octree/linear_octree.h"

namespace isovdb::octree {

/// Leaf counts of an octree.
struct OctreeSummary {
  std::vector<std::size_t> leavesPerDepth;         ///< index = depth (0 .. finest depth)
  std::vector<std::size_t> surfaceLeavesPerDepth;  ///< leaves the surface crosses, per depth
  std::size_t leaves = 0;
  std::size_t surfaceLeaves = 0;
  std::size_t complexLeaves = 0;  ///< complex leaves left at the maximum depth
  int minLeafDepth = 0;           ///< shallowest leaf depth
  int maxLeafDepth = 0;           ///< deepest leaf depth
};

/// @brief Counts leaves per depth and surface leaves.
OctreeSummary summarizeOctree(const LinearOctree& octree);

/// Options of writeLeafWireframe.
struct WireframeOptions {
  bool surfaceLeavesOnly = true;  ///< write only leaves the surface crosses (false: every leaf)
  bool binary = true;             ///< binary little-endian PLY (false: ASCII)
};

/// @brief Writes the leaf cells as a PLY wireframe: `vertex` (float x, y, z in
///        global voxel index coordinates, plus uchar depth) and `edge` (int
///        vertex1, vertex2) elements, 8 vertices and 12 edges per leaf.
///        Written to a temporary file beside `path`, then renamed.
/// @throw IoError if the file cannot be written.
void writeLeafWireframe(const LinearOctree& octree, const std::filesystem::path& path,
                        const WireframeOptions& options = {});

}  // namespace isovdb::octree
