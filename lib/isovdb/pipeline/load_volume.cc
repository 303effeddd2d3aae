// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/load_volume.h"

#include <cmath>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/dense_volume.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/sample_statistics.h"
#include "isovdb/store/segy_metadata.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/volume/ingest.h"

namespace isovdb::pipeline {

bool isVdbPath(const std::filesystem::path& path) { return io::lowerExtension(path) == ".vdb"; }

Statistics::Json distanceFieldSection(const volume::DistanceFieldOptions& options) {
  Statistics::Json section = Statistics::Json::object();
  section["method"] = std::string(volume::distanceMethodName(options.method));
  section["half_width_voxels"] = options.halfWidth;
  section["closing_steps"] = options.closingSteps;
  return section;
}

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

namespace {

Statistics::Json lineAxisJson(const io::SegyLineAxis& axis) {
  return {{"first", axis.first},
          {"last", axis.last()},
          {"step", axis.step},
          {"count", axis.count},
          {"spacing", axis.spacing}};
}

Statistics::Json segyJson(const io::SegyGeometry& g) {
  Statistics::Json json = Statistics::Json::object();
  json["revision"] = std::to_string(g.revision) + "." + std::to_string(g.revisionMinor);
  json["extended_text_headers"] = g.extendedTextHeaders;
  if (g.extendedTextHeaderCountVariable) json["extended_text_headers_ended_by_endtext"] = true;
  json["trace_header_extensions"] = g.traceHeaderExtensions;
  json["sample_format"] = io::segyFormatName(g.formatCode);
  json["byte_order"] = g.littleEndian ? "little-endian" : "big-endian";
  json["sorting"] = g.sorting == io::SegySorting::Inline ? "inline" : "crossline";
  json["header_bytes"] = {{"inline", g.bytes.inlineByte}, {"crossline", g.bytes.crosslineByte}};
  json["traces"] = g.traces;
  json["missing_traces"] = g.missingTraces;
  json["inlines"] = lineAxisJson(g.inlines);
  json["crosslines"] = lineAxisJson(g.crosslines);
  json["samples"] = g.samples;
  json["sample_interval_us"] = g.sampleIntervalUs;
  json["first_sample_ms"] = g.firstSampleMs;
  json["spacing_from_cdp_coordinates"] = g.spacingFromCoordinates;
  json["origin_cdp"] = g.originCdp;
  json["rotation_deg"] = g.rotationDegrees;
  return json;
}

Statistics::Json samplesJson(const io::SampleStatistics& statistics) {
  const io::SampleSummary& s = statistics.summary();
  Statistics::Json json = Statistics::Json::object();
  json["count"] = s.samples;
  json["holes"] = s.holes;
  json["min"] = s.minValue;
  json["max"] = s.maxValue;
  Statistics::Json& percentiles = json["percentiles"];
  for (const double p : {1.0, 5.0, 25.0, 50.0, 75.0, 95.0, 99.0})
    percentiles["p" + std::to_string(static_cast<int>(p))] = statistics.percentile(p);
  Statistics::Json& magnitudes = json["abs_percentiles"];
  for (const double p : {50.0, 75.0, 90.0, 95.0, 99.0})
    magnitudes["p" + std::to_string(static_cast<int>(p))] = statistics.absPercentile(p);
  json["clip"] = s.clip;
  json["active_fraction"] = s.activeFraction();
  return json;
}

/// Ingests a stream as a mask or a scalar field, gathering sample statistics on the way when asked.
volume::Volume ingest(io::SliceStream& stream, const InputOptions& options, Interrupter* interrupter,
                      Statistics::Json& input) {
  std::optional<io::SampleStatistics> statistics;
  std::optional<io::ObservedSliceStream> observed;
  std::optional<io::SliceWindowStream> windowed;
  io::SliceStream* source = &stream;
  if (options.window) {
    source = &windowed.emplace(stream, *options.window);
    input["window_z"] = {options.window->begin, options.window->end};
  }
  if (options.sampleStatistics) {
    statistics.emplace(options.clip);
    source = &observed.emplace(*source, *statistics);
  }
  volume::Volume result;
  if (options.denseAs == DenseAs::Mask) {
    input["mask_rule"] = options.rule.describe();
    result = volume::ingestMask(*source, options.rule, interrupter);
  } else {
    if (!(options.clip >= 0) || !std::isfinite(options.clip))  // NaN fails both comparisons
      throw InputError("--clip: must be a finite number >= 0, got " + std::to_string(options.clip));
    if (options.clip > 0) input["clip"] = options.clip;
    result = volume::ingestScalar(*source, {.background = options.clip, .deadBand = options.clip}, interrupter);
  }
  if (statistics) input["samples"] = samplesJson(*statistics);
  return result;
}

}  // namespace

volume::Volume loadVolume(const std::filesystem::path& path, const InputOptions& options, Interrupter* interrupter,
                          Statistics* stats) {
  Statistics::StageTimer timer(stats, "read");
  volume::Volume result;
  Statistics::Json input = Statistics::Json::object();
  input["path"] = path.string();
  if (isVdbPath(path)) {
    input["format"] = "vdb";
    if (options.window) {
      std::optional<volume::IndexBox> fileBox;
      result = store::readVdb(path, options.gridName, {options.window->begin, options.window->end}, &fileBox);
      input["window_z"] = {options.window->begin, options.window->end};
      if (fileBox) {
        input["file_bbox_min"] = fileBox->min;
        input["file_bbox_max"] = fileBox->max;
      }
    } else {
      result = store::readVdb(path, options.gridName);
    }
  } else if (options.segy || io::isSegyPath(path)) {
    const std::unique_ptr<io::SegyStream> stream = io::openSegy(path, options.segy.value_or(io::SegyOptions{}));
    input["format"] = "segy";
    input["segy"] = segyJson(stream->geometry());
    result = ingest(*stream, options, interrupter, input);
    store::recordSegyMetadata(result, stream->geometry());
  } else {
    std::unique_ptr<io::SliceStream> stream = io::openDenseVolume(path, options.raw);
    const io::VolumeHeader& header = stream->header();
    input["format"] = "dense";
    input["dims"] = header.dims;
    input["sample_type"] = std::string(io::sampleTypeName(header.sampleType));
    result = ingest(*stream, options, interrupter, input);
  }
  recordGridStats(result, input);
  if (stats) (*stats)["input"] = input;
  return result;
}

}  // namespace isovdb::pipeline
