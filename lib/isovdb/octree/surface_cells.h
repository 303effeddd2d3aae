// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file surface_cells.h
/// @brief Regular mode's tree as contouring reads it: only the 1-voxel cells the
///        surface crosses.
///
/// The regular construction (build.h) refines every cell whose samples are not all
/// one phase down to the maximum depth, so at 1-voxel cells its surface leaves are
/// exactly the unit cells whose eight corners differ, and every other leaf holds
/// neither a dual vertex nor a bipolar edge (the four cells around a bipolar edge
/// all contain it, so all are surface cells). Regular contouring reads nothing
/// else. Listing those cells straight from the phase bits, four rows at a time,
/// costs a fraction of the top-down construction, which evaluated and stored the
/// empty leaves too (more than half of the leaves on a surface-heavy volume).
#pragma once

#include "isovdb/cell/contour_settings.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/octree/build.h"
#include "isovdb/octree/linear_octree.h"

namespace isovdb::octree {

/// @brief The unit cells of the meta-cell whose corners are not all one phase
///        (inside iff value <= iso), in Z order: a partial LinearOctree whose
///        leaves are the regular octree's surface leaves at 1-voxel cells, with the
///        same keys and corner signs.
LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, float iso);
/// @brief The same from the samples' phases at the isovalue, already computed.
LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, const SamplePhases& phases);

/// @brief True if contouring with these settings reads only the surface cells of
///        a regular tree with 1-voxel leaves (surfaceCellTree gives the same mesh
///        as buildOctree): regular mode, 1-voxel cells at the maximum depth, and
///        the default interior-component detection.
bool contourReadsOnlySurfaceCells(const cell::ContourSettings& settings, const OctreeOptions& options,
                                  int metaCellSize);

/// @brief The tree the contouring of one meta-cell reads: surfaceCellTree where
///        contourReadsOnlySurfaceCells, else buildOctree (arguments as buildOctree's).
LinearOctree buildContourTree(const cell::MetaCellSamples& samples, const cell::ContourSettings& settings,
                              const OctreeOptions& options = {}, OctreeBuildStats* stats = nullptr,
                              Interrupter* interrupter = nullptr, const UnitEdgeCrossings* crossings = nullptr,
                              const SamplePhases* phases = nullptr, BuildMemo* memo = nullptr);

}  // namespace isovdb::octree
