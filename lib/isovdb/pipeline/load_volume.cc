#include "isovdb/pipeline/load_volume.h"

#include <string>

#include "isovdb/io/dense_volume.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/vdb_file.h"
#include "isovdb/volume/ingest.h"

namespace isovdb::pipeline {

bool isVdbPath(const std::filesystem::path& path) { return io::lowerExtension(path) == ".vdb"; }

void recordGridStats(const volume::Volume& volume, Statistics::Json& section) {
  const volume::GridStats stats = volume.stats();
  section["kind"] = std::string(volume::volumeKindName(volume.kind()));
  section["active_voxels"] = stats.activeVoxels;
  section["leaf_nodes"] = stats.leafCount;
  section["active_tiles"] = stats.tileCount;
  section["grid_memory_bytes"] = stats.memoryBytes;
  section["bbox_min"] = stats.bboxMin;
  section["bbox_max"] = stats.bboxMax;
  section["spacing"] = volume.geometry().spacing;
  section["origin"] = volume.geometry().origin;
  if (volume.kind() != volume::VolumeKind::Mask) {
    section["min_value"] = stats.minValue;
    section["max_value"] = stats.maxValue;
  }
}

volume::Volume loadVolume(const std::filesystem::path& path, const InputOptions& options,
                          Interrupter* interrupter, Statistics* stats) {
  Statistics::StageTimer timer(stats, "read");
  volume::Volume result;
  Statistics::Json input = Statistics::Json::object();
  input["path"] = path.string();
  if (isVdbPath(path)) {
    input["format"] = "vdb";
    result = io::readVdb(path, options.gridName);
  } else {
    std::unique_ptr<io::SliceStream> stream = io::openDenseVolume(path, options.raw);
    const io::VolumeHeader& header = stream->header();
    input["format"] = "dense";
    input["dims"] = header.dims;
    input["sample_type"] = std::string(io::sampleTypeName(header.sampleType));
    if (options.denseAs == DenseAs::Mask) {
      input["mask_rule"] = options.rule.describe();
      result = volume::ingestMask(*stream, options.rule, interrupter);
    } else {
      result = volume::ingestScalar(*stream, {}, interrupter);
    }
  }
  recordGridStats(result, input);
  if (stats) (*stats)["input"] = input;
  return result;
}

}  // namespace isovdb::pipeline
