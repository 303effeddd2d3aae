// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file segy_writer.h
/// @brief A small SEG-Y writer for synthetic cubes: test inputs built in code and
///        large benchmark cubes, written trace by trace (memory: one trace).
///
/// Writes SEG-Y rev 1 layouts: a 3200-byte textual header (ASCII), the binary
/// header (interval, samples, format, revision), and per trace a 240-byte
/// header (trace sequence number, inline and crossline numbers at configurable
/// 4-byte fields, CDP X/Y with scalar -10, sample count and interval, delay)
/// and its samples. Byte order big-endian, or the whole file little-endian.
#pragma once

#include <filesystem>
#include <functional>

namespace isovdb::samples {

/// The geometry and encoding of a synthetic cube.
struct SegyCubeSpec {
  int inlines = 10;     ///< lines along grid x
  int crosslines = 10;  ///< lines along grid y
  int samples = 50;     ///< samples per trace (grid z)
  int firstInline = 1, inlineStep = 1;
  int firstCrossline = 1, crosslineStep = 1;
  int formatCode = 5;            ///< 1 IBM float, 2 int32, 3 int16, 5 IEEE float, 8 int8 (any code is written as is)
  bool littleEndian = false;     ///< byte-swap the whole file
  bool crosslineSorted = false;  ///< traces ordered crossline by crossline
  int sampleIntervalUs = 4000;
  int delayMs = 0;                 ///< trace header byte 109
  int inlineByte = 189;            ///< 4-byte trace header field of the inline number
  int crosslineByte = 193;         ///< 4-byte trace header field of the crossline number
  double inlineSpacing = 25.0;     ///< CDP Y grows by this per inline index (written in decimetres)
  double crosslineSpacing = 25.0;  ///< CDP X grows by this per crossline index
};

/// Fills one trace (spec.samples values) of inline index i, crossline index j
/// (0-based); returns false to leave that position without a trace (a hole).
using TraceFunction = std::function<bool(int i, int j, float* trace)>;

/// Writes the cube to `path` through a temporary file (nothing partial on failure).
/// Integer formats round and clamp the values. Returns the number of traces written.
/// @throw IoError when the file cannot be written.
long long writeSegyCube(const std::filesystem::path& path, const SegyCubeSpec& spec, const TraceFunction& trace);

}  // namespace isovdb::samples
