// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file segy_metadata.h
/// @brief A SEG-Y cube's survey geometry kept in its grid's metadata, so a `.vdb`
///        export tells other VDB tools where the samples came from.
#pragma once

#include "isovdb/io/segy_reader.h"
#include "isovdb/volume/volume.h"

namespace isovdb::store {

/// Adds `segy_inline_first/last/step`, `segy_crossline_first/last/step`,
/// `segy_sample_interval_us`, `segy_first_sample_ms`, `segy_format`, `segy_sorting`,
/// `segy_missing_traces`, `segy_origin_cdp_x/y` and `segy_rotation_deg` to the
/// volume's grid (world units: x, y in CDP units, z in ms; see segy_reader.h).
/// @pre volume.valid()
void recordSegyMetadata(const volume::Volume& volume, const io::SegyGeometry& geometry);

}  // namespace isovdb::store
