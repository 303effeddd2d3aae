// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/segy_metadata.h"

#include "isovdb/volume/grids.h"

namespace isovdb::store {

void recordSegyMetadata(const volume::Volume& volume, const io::SegyGeometry& geometry) {
  openvdb::GridBase& grid = *volume.grid();
  const auto addAxis = [&](const std::string& name, const io::SegyLineAxis& axis) {
    grid.insertMeta("segy_" + name + "_first", openvdb::Int32Metadata(axis.first));
    grid.insertMeta("segy_" + name + "_last", openvdb::Int32Metadata(axis.last()));
    grid.insertMeta("segy_" + name + "_step", openvdb::Int32Metadata(axis.step));
  };
  addAxis("inline", geometry.inlines);
  addAxis("crossline", geometry.crosslines);
  grid.insertMeta("segy_sample_interval_us", openvdb::DoubleMetadata(geometry.sampleIntervalUs));
  grid.insertMeta("segy_first_sample_ms", openvdb::DoubleMetadata(geometry.firstSampleMs));
  grid.insertMeta("segy_format", openvdb::StringMetadata(io::segyFormatName(geometry.formatCode)));
  grid.insertMeta("segy_sorting",
                  openvdb::StringMetadata(geometry.sorting == io::SegySorting::Inline ? "inline" : "crossline"));
  grid.insertMeta("segy_missing_traces", openvdb::Int64Metadata(geometry.missingTraces));
  grid.insertMeta("segy_origin_cdp_x", openvdb::DoubleMetadata(geometry.originCdp[0]));
  grid.insertMeta("segy_origin_cdp_y", openvdb::DoubleMetadata(geometry.originCdp[1]));
  grid.insertMeta("segy_rotation_deg", openvdb::DoubleMetadata(geometry.rotationDegrees));
}

}  // namespace isovdb::store
