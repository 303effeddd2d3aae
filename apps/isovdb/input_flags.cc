// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "input_flags.h"

#include "isovdb/errors.h"

namespace isovdb::cli {

void InputFlags::add(CLI::App& command, bool rawSpacing) {
  command.add_option("--dims", dims, "Raw volumes: samples along x,y,z (e.g. 256,256,128)")
      ->delimiter(',')
      ->expected(3);
  command.add_option("--type", type, "Raw volumes: sample type (uint8, uint16, float32, int16, ...)");
  command.add_flag("--big-endian", bigEndian, "Raw volumes: samples are big-endian");
  if (rawSpacing)
    command.add_option("--spacing", spacing, "Raw volumes: voxel size x,y,z in world units (default 1,1,1)")
        ->delimiter(',')
        ->expected(3);
  command.add_option("--header-bytes", headerBytes, "Raw volumes: bytes to skip before the samples");
  command.add_option("--threshold", threshold, "Mask: inside = value > THRESHOLD (default 0)");
  command.add_option("--labels", labels, "Mask: inside = value is one of these labels (e.g. 13 or 3,4)")
      ->delimiter(',');
  command.add_flag("--scalar", scalar, "Contour the samples as a scalar field at --iso instead of a mask");
  command.add_option("--grid", grid, ".vdb inputs: name of the grid to read (default: first float/bool grid)");
  seismic.add(command);
}

pipeline::InputOptions InputFlags::toOptions(const std::string& path) const {
  pipeline::InputChoices choices;
  choices.threshold = threshold;
  choices.labels = labels;
  choices.scalar = scalar;
  choices.grid = grid;
  if (!dims.empty() || !type.empty()) {
    if (dims.empty()) throw InputError("'" + path + "': --type given without --dims X,Y,Z");
    if (type.empty()) throw InputError("'" + path + "': --dims given without --type");
    const auto sampleType = io::parseSampleType(type);
    if (!sampleType)
      throw InputError("'" + path + "': unknown sample type '" + type +
                       "', expected uint8, int8, uint16, int16, uint32, int32, float32 or float64");
    io::RawOptions raw;
    raw.dims = {dims[0], dims[1], dims[2]};
    raw.type = *sampleType;
    raw.bigEndian = bigEndian;
    if (!spacing.empty()) raw.spacing = {spacing[0], spacing[1], spacing[2]};
    raw.headerBytes = headerBytes;
    choices.raw = raw;
  }
  seismic.fill(choices);
  return pipeline::resolveInputChoices(path, choices);
}

}  // namespace isovdb::cli
