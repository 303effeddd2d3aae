// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file digital_topology.h
/// @brief Topological invariants of a voxel object, computed in one streaming pass.
///
/// Coordinates: voxel index space. Voxel (i, j, k) is the closed unit cube
/// [i, i+1] x [j, j+1] x [k, k+1] of the cubical complex; the object is the
/// union of the cubes of its foreground (inside) voxels. This is the
/// (26, 6) digital topology: foreground voxels that share a face, an edge or
/// a corner are connected (26-adjacency), background voxels only through
/// faces (6-adjacency). Everything outside the volume is background.
///
/// For a solid object, the Euler characteristic is
///   chi = components - handles (tunnels) + cavities,
/// so a ball has chi = 1, a solid torus 0, a hollow ball 2.
#pragma once

#include <cstdint>

#include "isovdb/io/slice_stream.h"
#include "isovdb/progress.h"
#include "isovdb/volume/mask_rule.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

/// Which voxels of the object count as connected.
enum class Adjacency {
  /// (26, 6): inside voxels sharing a face, an edge or a corner are connected
  /// (the union of closed voxel cubes described above).
  Foreground26,
  /// (6, 18): inside voxels connect only through faces, background voxels
  /// through faces or edges. Dual Marching Cubes on the distance field (regular
  /// mode) resolves every ambiguity this way, except where Wenger's manifold fix
  /// regroups a pair of cells: each such pair changes the mesh's χ by 2.
  Foreground6,
};

/// @brief Euler characteristic chi = V - E + F - C of the union of the closed
///        unit cubes of the voxels that `rule` classifies as inside.
///
/// Method: every cell of the cubical complex (vertex, edge, square, cube) is
/// owned by its lowest lattice vertex p; whether each of the 8 cells owned by p
/// belongs to the object depends only on the 2x2x2 voxels around p, so chi is
/// a sum over lattice vertices of a 256-entry table lookup. Vertices on the
/// volume boundary see the outside as background.
///
/// @param[in,out] stream  read from its next slice to the last one (normally
///                        a freshly opened stream; slices already read are skipped).
/// @param[in] rule        which sample values are inside.
/// @param[in] interrupter optional progress/cancellation, polled once per slice.
/// @param[in] adjacency   Foreground26 (the closed-cube complex described above) or
///                        Foreground6 (see Adjacency).
/// @return chi of the object (0 for an empty object).
/// @throw InputError / IoError from the stream; Interrupted on cancellation.
/// @note Memory: one float slice and two byte slices (O(slice)); slices are
///       processed in parallel by rows (TBB).
std::int64_t eulerCharacteristic(io::SliceStream& stream, const MaskRule& rule, Interrupter* interrupter = nullptr,
                                 Adjacency adjacency = Adjacency::Foreground26);

/// @brief Euler characteristic of a mask volume (BoolGrid, active voxel = inside),
///        with the same (26, 6) convention and method as the stream version.
///
/// Walks the active bounding box slice by slice; active tiles count as
/// inside like the voxels they cover.
/// @param[in] mask  a VolumeKind::Mask volume.
/// @param[in] interrupter optional progress/cancellation, polled once per slice.
/// @throw InputError when `mask` is not a mask volume; Interrupted on cancellation.
/// @note Memory: two byte slices of the active bounding box (O(slice)).
std::int64_t eulerCharacteristic(const Volume& mask, Interrupter* interrupter = nullptr,
                                 Adjacency adjacency = Adjacency::Foreground26);

}  // namespace isovdb::volume
