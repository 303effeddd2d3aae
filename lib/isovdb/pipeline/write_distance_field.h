// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file write_distance_field.h
/// @brief `isovdb sdf`'s job: a volume's narrow-band distance field written to a
///        level-set .vdb. From a mask, the band goes to the file chunk by chunk
///        (store::LeafwiseLevelSetWriter), so it is never held whole: peak memory is
///        the mask, the chunks in flight and about 90 bytes per band leaf.
#pragma once

#include <filesystem>
#include <string>

#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

/// Writes the distance field of `volume` to `output` as one level-set grid named
/// `gridName`. A mask is streamed chunk by chunk (Tracker with chunkSize 0: computed
/// whole first); other volumes are written as they are.
/// Figures go to stats ("distance_field", "output", stage timings) when given.
/// @throw InputError for options out of range; IoError when
///        the output cannot be written (nothing is left at `output` then).
void writeDistanceFieldVdb(const volume::Volume& volume, const volume::DistanceFieldOptions& options,
                           const std::filesystem::path& output, const std::string& gridName,
                           Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

}  // namespace isovdb::pipeline
