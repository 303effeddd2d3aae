// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file ingest.h
/// @brief Streaming ingest of a dense volume into a sparse OpenVDB grid, slab by slab.
///
/// Memory: one slab of 8 z-slices (one leaf node deep) plus the sparse grid;
/// the dense volume is never held. Homogeneous 8^3 blocks become tiles of the
/// level-1 internal nodes, homogeneous 128^3 blocks become tiles of the level-2
/// nodes (pruned every 128 slices), so the grid's size follows the surface.
/// Output is in voxel index space, axes permuted by VolumeHeader::gridAxis; the
/// file's spacing/origin go to Volume::geometry() and its dims to sampledBox().
/// Mask ingest: NaN samples (holes) are outside.
#pragma once

#include "isovdb/io/slice_stream.h"
#include "isovdb/progress.h"
#include "isovdb/volume/mask_rule.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

/// Binary mask: voxel active (and true) iff `rule.inside(value)`.
/// @throw InputError / IoError from the stream (message names the file).
/// @throw Interrupted when `interrupter` asks to stop.
Volume ingestMask(io::SliceStream& stream, const MaskRule& rule, Interrupter* interrupter = nullptr);

struct ScalarIngestOptions {
  /// Value of the grid's background (inactive space). Leaves whose 512 samples all
  /// equal it (within `tolerance`) are not stored.
  float background = 0.f;
  /// Blocks whose values differ from one another by at most this much collapse
  /// into tiles. 0 keeps the data exactly.
  float tolerance = 0.f;
  /// Dead band: samples with |value| < deadBand stay inactive (they read as the
  /// background), so a mostly quiet amplitude cube costs little. 0 keeps every
  /// sample. Seismic cubes use background = deadBand = the clip value.
  float deadBand = 0.f;
};

/// Scalar field: a FloatGrid holding the samples, constant blocks as tiles.
/// NaN samples (holes: SEG-Y positions without a trace) stay inactive. The dead
/// band, when > 0, is recorded in the grid's metadata (deadBandOf()).
/// @throw InputError / IoError from the stream; Interrupted on cancellation.
Volume ingestScalar(io::SliceStream& stream, const ScalarIngestOptions& options = {},
                    Interrupter* interrupter = nullptr);

/// Signed distances (world units, negative inside: OpenVDB's, scikit-fmm's and most SDF
/// tools' convention), e.g. a dense SDF array, as the engine's narrow-band distance field:
/// values in voxels, samples with |distance| >= `halfWidth` voxels inactive at
/// +-halfWidth, beyond the samples outside. The sampled box is recorded as ingestScalar
/// records it, so surfaces that reach the data's end are capped.
/// @throw InputError for non-uniform voxels (a distance has one unit), a half-width below
///        1, or from the stream; Interrupted on cancellation.
Volume ingestSignedDistances(io::SliceStream& stream, int halfWidth = 3, Interrupter* interrupter = nullptr);

/// The dead band a Scalar volume was ingested with (0 when none).
float deadBandOf(const Volume& volume);

}  // namespace isovdb::volume
