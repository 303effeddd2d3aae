// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/segy_metadata.h"

#include "isovdb/volume/grids.h"

namespace isovdb::io {

void recordSegyMetadata(const volume::Volume& volume, const SegyGeometry& geometry) {
  openvdb::GridBase& grid = *volume.grid();
  const auto addAxis = [&](const std::string& name, const SegyLineAxis& axis) {
    grid.insertMeta("segy_" + name + "_first", openvdb::Int32Metadata(axis.first));
    grid.insertMeta("segy_" + name + "_last", openvdb::Int32Metadata(axis.last()));
    grid.insertMeta("segy_" + name + "_step", openvdb::Int32Metadata(axis.step));
  };
  addAxis("inline", geometry.inlines);
  addAxis("crossline", geometry.crosslines);
  grid.insertMeta("segy_sample_interval_us", openvdb::DoubleMetadata(geometry.sampleIntervalUs));
  grid.insertMeta("segy_first_sample_ms", openvdb::DoubleMetadata(geometry.firstSampleMs));
  grid.insertMeta("segy_format", openvdb::StringMetadata(segyFormatName(geometry.formatCode)));
  grid.insertMeta("segy_sorting",
                  openvdb::StringMetadata(geometry.sorting == SegySorting::Inline ? "inline" : "crossline"));
  grid.insertMeta("segy_missing_traces", openvdb::Int64Metadata(geometry.missingTraces));
  grid.insertMeta("segy_origin_cdp_x", openvdb::DoubleMetadata(geometry.originCdp[0]));
  grid.insertMeta("segy_origin_cdp_y", openvdb::DoubleMetadata(geometry.originCdp[1]));
  grid.insertMeta("segy_rotation_deg", openvdb::DoubleMetadata(geometry.rotationDegrees));
}

}  // namespace isovdb::io
