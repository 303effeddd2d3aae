// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file segy_reader.h
/// @brief SEG-Y (rev 0, 1 and 2) post-stack amplitude cubes, read trace by trace
///        with segyio's C API, as a SliceStream.
///
/// Geometry comes from the trace headers: the inline and crossline numbers
/// (bytes 189/193 by default, configurable), the sorting (which number stays
/// constant over consecutive traces), the CDP coordinates (bytes 181/185,
/// scaled by byte 71) for the line spacings, the sample interval (binary header
/// byte 3217 or trace header byte 117) and the delay of the first sample (trace
/// header byte 109, scaled by byte 215). Byte order is detected from the binary
/// header's format code. Revision 2: a variable count of extended textual
/// headers (-1, ended by ((SEG: EndText))), the extended sample count (bytes
/// 3269-3272) and trace header extensions (bytes 3507-3508: skipped; the
/// geometry comes from the standard header). Sample counts are unsigned.
///
/// Grid axes: x = inline index, y = crossline index, z = sample index (time or
/// depth grows with z): with inlines north and crosslines east, a right-handed
/// north-east-down frame. Index i on an axis is line number first + i * step;
/// positions without a trace (irregular surveys, missing traces) are holes:
/// their samples read as NaN and stay inactive in the grid.
/// World units: x and y in the CDP coordinate unit (metres, usually), z in
/// milliseconds of the sample interval (microseconds / 1000).
///
/// Memory: the scan keeps 8 bytes per trace while it runs and 4 after; a slice
/// is one line of the file (traces of one inline, or crossline, for a
/// crossline-sorted file). The dense cube is never held.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// What a SEG-Y file does not always say the standard way (CLI: --inline-byte,
/// --crossline-byte).
struct SegyOptions {
  int inlineByte = 189;     ///< trace header byte (1-based) of the inline number (SEG-Y rev 1: 189)
  int crosslineByte = 193;  ///< trace header byte (1-based) of the crossline number (SEG-Y rev 1: 193)
};

/// Which line number stays constant over consecutive traces.
enum class SegySorting { Inline, Crossline };

/// Line numbers along one grid axis: index i is line first + i * step.
struct SegyLineAxis {
  int first = 0;
  int step = 1;  ///< non-zero; negative when the file's lines run downwards
  int count = 0;
  double spacing = 1.0;  ///< world distance between neighbouring indices (CDP units)
  int last() const { return first + (count - 1) * step; }
};

/// Everything the header scan found.
struct SegyGeometry {
  int formatCode = 1;         ///< SEG-Y sample format: 1 IBM float, 2 int32, 3 int16, 5 IEEE float, 8 int8
  bool littleEndian = false;  ///< whole file byte-swapped (SEG-Y rev 2 / Seismic Unix style)
  SegySorting sorting = SegySorting::Inline;
  int samples = 0;                   ///< samples per trace
  double sampleIntervalUs = 4000.0;  ///< microseconds (or the depth unit / 1000)
  double firstSampleMs = 0.0;        ///< delay recording time of the first trace (byte 109)
  std::int64_t traces = 0;           ///< traces in the file
  std::int64_t missingTraces = 0;    ///< inline/crossline positions without a trace
  SegyLineAxis inlines, crosslines;
  /// Line spacings come from CDP coordinates; false when the file has none (spacing 1 per line).
  bool spacingFromCoordinates = false;
  std::array<double, 2> originCdp{0.0, 0.0};     ///< CDP X, Y of index (0, 0) (extrapolated if it is a hole)
  double rotationDegrees = 0.0;                  ///< azimuth of the inline axis (x), clockwise from CDP-Y ("north")
  SegyOptions bytes;                             ///< the header byte positions used
  int revision = 0;                              ///< SEG-Y major revision (binary header byte 3501)
  int revisionMinor = 0;                         ///< minor revision (byte 3502)
  int extendedTextHeaders = 0;                   ///< 3200-byte headers after the binary one (bytes 3505-3506)
  bool extendedTextHeaderCountVariable = false;  ///< -1 in the binary header: counted up to ((SEG: EndText))
  int traceHeaderExtensions = 0;  ///< 240-byte headers after each trace header (rev 2, bytes 3507-3508), skipped
};

/// "IBM float", "int32", "int16", "IEEE float" or "int8".
std::string segyFormatName(int formatCode);

/// True for the .sgy and .segy extensions (case-insensitive).
bool isSegyPath(const std::filesystem::path& path);

/// A SEG-Y cube streamed one file line at a time. Stream axes: x = sample,
/// y = position along the line, z = line (VolumeHeader::gridAxis maps them to
/// inline, crossline, sample).
class SegyStream final : public SliceStream {
 public:
  ~SegyStream() override;
  const std::string& source() const override { return source_; }
  const VolumeHeader& header() const override { return header_; }
  const SegyGeometry& geometry() const { return geometry_; }

  /// Reads the traces of the next line; holes are NaN.
  /// @throw InputError "'f.sgy': trace T (inline I, crossline X) sample S is NaN" for
  ///        non-finite IEEE samples; IoError when the OS read fails.
  void readSlice(float* out) override;
  std::int64_t nextSlice() const override { return nextSlice_; }

 private:
  friend std::unique_ptr<SegyStream> openSegy(const std::filesystem::path&, const SegyOptions&);
  SegyStream() = default;

 public:
  struct File;  ///< segyio's handle and trace layout (defined in the .cc)

 private:
  std::string source_;
  VolumeHeader header_;
  SegyGeometry geometry_;
  std::unique_ptr<File> file_;
  std::vector<std::int64_t> lineFirstTrace_;   ///< per line index: first trace, -1 for a missing line
  std::vector<std::int32_t> lineTraceCount_;   ///< per line index: traces in the file
  std::vector<std::int32_t> positionOfTrace_;  ///< per trace: index along its line
  std::vector<char> traceBytes_;
  std::int64_t nextSlice_ = 0;
};

/// Opens a SEG-Y file and scans its headers (one read of every trace header).
/// @throw IoError "'path': no such file" (or the OS reason);
///        InputError naming the file and the problem: shorter than the 3600 header
///        bytes ("file ends after the textual header"), an unsupported sample
///        format code, no traces, a size that is not a whole number of traces
///        (truncated file or wrong sample count), a byte position that is not a
///        trace header field, line numbers that are not monotonic in the sorting
///        order, two traces at the same inline and crossline, or line numbers
///        that fill less than a quarter of their grid (the byte positions are wrong).
std::unique_ptr<SegyStream> openSegy(const std::filesystem::path& path, const SegyOptions& options = {});

}  // namespace isovdb::io
