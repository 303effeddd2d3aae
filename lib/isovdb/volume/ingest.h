/// @file ingest.h
/// @brief Streaming ingest of a dense volume into a sparse OpenVDB grid, slab by slab.
///
/// Memory: one slab of 8 z-slices (one leaf node deep) plus the sparse grid;
/// the dense volume is never held. Homogeneous 8^3 blocks become tiles of the
/// level-1 internal nodes, homogeneous 128^3 blocks become tiles of the level-2
/// nodes (pruned every 128 slices), so the grid's size follows the surface.
/// Output is in voxel index space; the file's spacing/origin go to Volume::geometry().
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
};

/// Scalar field: a FloatGrid holding the samples, constant blocks as tiles.
/// @throw InputError / IoError from the stream; Interrupted on cancellation.
Volume ingestScalar(io::SliceStream& stream, const ScalarIngestOptions& options = {},
                    Interrupter* interrupter = nullptr);

}  // namespace isovdb::volume
