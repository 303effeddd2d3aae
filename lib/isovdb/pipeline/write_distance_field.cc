// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/write_distance_field.h"

#include "isovdb/store/leafwise_level_set_writer.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/volume/band_chunks.h"

namespace isovdb::pipeline {

void writeDistanceFieldVdb(const volume::Volume& volume, const volume::DistanceFieldOptions& options,
                           const std::filesystem::path& output, const std::string& gridName, Interrupter* interrupter,
                           Statistics* stats) {
  volume::checkDistanceFieldOptions(options);
  const bool wholeInMemory = options.chunkSize == 0 && options.method == volume::DistanceMethod::Tracker;
  if (volume.kind() != volume::VolumeKind::Mask || wholeInMemory) {
    const volume::Volume sdf = toContourable(volume, options, interrupter, stats);
    Statistics::StageTimer timer(stats, "write");
    store::writeVdb(output, sdf, {.gridName = gridName});
    return;
  }
  store::LeafwiseLevelSetWriter writer(output, static_cast<float>(options.halfWidth), volume.geometry(),
                                       {.gridName = gridName, .source = volume.name()});
  {
    Statistics::StageTimer timer(stats, "distance_field");
    volume::computeBandInChunks(
        volume::maskGrid(volume), options, [&writer](auto&& leaves) { writer.add(std::move(leaves)); }, interrupter);
  }
  store::LevelSetFileSummary summary;
  {
    Statistics::StageTimer timer(stats, "write");
    summary = writer.commit(interrupter);
  }
  if (!stats) return;
  Statistics::Json section = distanceFieldSection(options);
  recordBandFigures(summary, volume.geometry(), section);
  // Streamed: the band was never a grid in memory, so there is no grid_memory_bytes.
  section["streamed_to_file"] = true;
  section["spill_bytes"] = summary.spillBytes;
  (*stats)["distance_field"] = section;
  (*stats)["output"]["file_bytes"] = summary.fileBytes;
}

}  // namespace isovdb::pipeline
