// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file inspect_octree.h
/// @brief `isovdb octree`: build the octree of one meta-cell and report it, so a
///        person can look at the tree (per-level counts, complex edges and faces,
///        optional wireframe of the leaves).
#pragma once

#include <filesystem>
#include <optional>

#include "isovdb/octree/build.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/meta_cells.h"

namespace isovdb::pipeline {

struct InspectOctreeOptions {
  /// The settings `isovdb extract` would run with (method, iso, octree, meta-cell
  /// size, distance field): the tree shown is the one extract builds there.
  ExtractOptions extract;
  std::optional<volume::MetaCellIndex> metaCell;  ///< empty: the first meta-cell the surface crosses
  std::filesystem::path wireframe;                ///< empty: none; else a PLY of the leaf cells
};

/// Records the partition ("meta_cells") and the chosen meta-cell's tree ("octree")
/// in `stats`. @throw InputError when the meta-cell is outside the grid or no
/// meta-cell holds the surface.
void inspectOctree(const volume::Volume& volume, const InspectOctreeOptions& options, Statistics& stats,
                   Interrupter* interrupter = nullptr);

}  // namespace isovdb::pipeline
