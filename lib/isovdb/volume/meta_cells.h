// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file meta_cells.h
/// @brief Partition of a distance field into meta-cells, and reading one meta-cell's
///        samples (paper 000 §4.2.1).
///
/// A meta-cell is a cube of S voxels (S a power of two; 128 aligns with OpenVDB's
/// level-1 internal nodes) whose S+1 samples per axis include its boundary, so
/// neighbours share their boundary samples. Meta-cell (i, j, k) covers index
/// samples [i*S, i*S + S] on x (likewise y, z). Memory: reading one meta-cell
/// costs (S+3)^3 floats (with the one-sample apron the Prewitt gradients need);
/// meta-cells that lie in tiles or hold no sign change are found without reading voxels.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/volume/sampled_box.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

using MetaCellIndex = std::array<int, 3>;

struct MetaCellPartition {
  int size = 128;                    ///< S, voxels per meta-cell edge
  std::vector<MetaCellIndex> cells;  ///< meta-cells the surface may cross, sorted z, y, x
  std::int64_t leavesScanned = 0;    ///< SDF leaves looked at (no voxel of a tile is read)
};

/// Meta-cells of size `size` that may hold a sign change of `field` across `iso`.
/// Distance field: those touching a leaf with a value within one voxel of the
/// isovalue (a distance field changes by at most one per voxel, so every
/// crossing lies in such a leaf); tiles are never read. Scalar field (values
/// may jump by any amount): those touching, grown by one voxel, an active tile
/// or a leaf whose samples lie on both sides of the isovalue, or on the other
/// side than a sample next to one of its faces (in the neighbouring leaf, tile
/// or background; beyond `capsBox` a sample reads as outside). A dense field's
/// blocks that the surface misses are then not read (a 256³ Gaussian's ball:
/// 8 meta-cells instead of 64). Callers still test each meta-cell's samples
/// (hasSignChange).
/// `capsBox`: the data's box when the contouring makes caps on it (outside it reads as
/// outside); where the grid's background is inside (a scalar's background at or above
/// the isovalue), the meta-cells along the box's faces are added too, since a cap may
/// close an inside region that holds no leaf.
/// @pre field is a DistanceField or Scalar volume; size is a power of two in [8, 4096].
/// @throw InputError otherwise.
MetaCellPartition partitionMetaCells(const Volume& field, int size, float iso = 0.f,
                                     const std::optional<IndexBox>& capsBox = std::nullopt);

/// True when the grid's background (inactive space) lies inside the surface at `iso`:
/// a scalar's at or above it, a distance field's at or below it.
bool backgroundInside(const Volume& field, float iso);

/// The value of every voxel of the leaf-sized block at this origin (multiples of 8)
/// where the grid holds no leaf; empty: the grid's own tile or background value.
using BlockWithoutLeaf = std::function<float(const std::array<int, 3>&)>;

/// Fills `out` with the samples of meta-cell `index` (offsets -A..S+A on each
/// axis, A = `apron`), inactive voxels reading as the grid's signed background.
void readMetaCell(const Volume& field, const MetaCellIndex& index, int size, cell::MetaCellSamples& out, int apron = 1,
                  const BlockWithoutLeaf& blockWithoutLeaf = {});

/// Fills `out` with the samples of the cube of `size` cells whose minimum corner
/// is `origin` (any index position, not only multiples of size), apron included.
void readBlock(const Volume& field, const std::array<int, 3>& origin, int size, cell::MetaCellSamples& out,
               int apron = 1, const BlockWithoutLeaf& blockWithoutLeaf = {});

/// True when the samples 0..S of `samples` hold both sides of `iso` (inside: value <= iso).
bool hasSignChange(const cell::MetaCellSamples& samples, float iso);

}  // namespace isovdb::volume
