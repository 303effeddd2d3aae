// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/segy_reader.h"

#include <segyio/segy.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>

#include "isovdb/errors.h"
#include "isovdb/io/path_util.h"

namespace isovdb::io {

struct SegyStream::File {
  segy_file* handle = nullptr;
  long trace0 = 0;     ///< byte offset of the first trace header
  int traceBytes = 0;  ///< sample bytes per trace (without the 240-byte header)
  ~File() {
    if (handle) segy_close(handle);
  }
};

namespace {

constexpr std::int64_t kHeaderBytes = SEGY_TEXT_HEADER_SIZE + SEGY_BINARY_HEADER_SIZE;

/// The sample type of a SEG-Y format code, as read by convertSamples() once
/// segyio has put the bytes in big-endian order (IBM floats are converted first).
std::optional<SampleType> sampleTypeOf(int formatCode) {
  switch (formatCode) {
    case SEGY_IBM_FLOAT_4_BYTE:
    case SEGY_IEEE_FLOAT_4_BYTE:
      return SampleType::Float32;
    case SEGY_SIGNED_INTEGER_4_BYTE:
      return SampleType::Int32;
    case SEGY_SIGNED_SHORT_2_BYTE:
      return SampleType::Int16;
    case SEGY_SIGNED_CHAR_1_BYTE:
      return SampleType::Int8;
    default:
      return std::nullopt;
  }
}

/// Reads what the scan needs from the file; every error names the file.
class HeaderScan {
 public:
  HeaderScan(std::string source, SegyStream::File& file) : where_("'" + std::move(source) + "': "), file_(file) {}

  InputError error(const std::string& what) const { return InputError(where_ + what); }

  void readBinaryHeader(char* buf) {
    if (segy_binheader(file_.handle, buf) != SEGY_OK) throw error("cannot read the binary header");
  }

  void readTraceHeader(std::int64_t trace, char* buf) {
    if (segy_traceheader(file_.handle, static_cast<int>(trace), buf, file_.trace0, file_.traceBytes) != SEGY_OK)
      throw IoError(where_ + "cannot read the header of trace " + std::to_string(trace));
  }

  int field(const char* header, int byte, const char* what) const {
    std::int32_t value = 0;
    if (segy_get_field(header, byte, &value) != SEGY_OK)
      throw error(std::string(what) + " " + std::to_string(byte) +
                  " is not the first byte of a SEG-Y trace header field");
    return value;
  }

 private:
  std::string where_;
  SegyStream::File& file_;
};

/// CDP X/Y of a trace header, with the coordinate scalar (byte 71) applied.
std::array<double, 2> cdpOf(const HeaderScan& scan, const char* header) {
  int scalar = scan.field(header, SEGY_TR_SOURCE_GROUP_SCALAR, "trace header byte");
  const double factor = scalar == 0 ? 1.0 : scalar > 0 ? scalar : 1.0 / -scalar;
  return {scan.field(header, SEGY_TR_CDP_X, "trace header byte") * factor,
          scan.field(header, SEGY_TR_CDP_Y, "trace header byte") * factor};
}

struct LineKeys {
  std::vector<std::int32_t> slow, fast;  ///< per trace: number of its line, and along the line
};

/// Index along a line axis whose numbers are first + i * step.
int indexOf(int number, const SegyLineAxis& axis) { return (number - axis.first) / axis.step; }

}  // namespace

std::string segyFormatName(int formatCode) {
  switch (formatCode) {
    case SEGY_IBM_FLOAT_4_BYTE:
      return "IBM float";
    case SEGY_SIGNED_INTEGER_4_BYTE:
      return "int32";
    case SEGY_SIGNED_SHORT_2_BYTE:
      return "int16";
    case SEGY_IEEE_FLOAT_4_BYTE:
      return "IEEE float";
    case SEGY_SIGNED_CHAR_1_BYTE:
      return "int8";
    default:
      return "format " + std::to_string(formatCode);
  }
}

bool isSegyPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".sgy" || ext == ".segy";
}

SegyStream::~SegyStream() = default;

std::unique_ptr<SegyStream> openSegy(const std::filesystem::path& path, const SegyOptions& options) {
  const std::string source = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError("'" + source + "': no such file");
  const auto fileSize = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
  if (ec) throw IoError("'" + source + "': " + ec.message());

  std::unique_ptr<SegyStream> stream(new SegyStream());
  stream->source_ = source;
  stream->file_ = std::make_unique<SegyStream::File>();
  SegyStream::File& file = *stream->file_;
  SegyGeometry& g = stream->geometry_;
  g.bytes = options;
  HeaderScan scan(source, file);

  if (fileSize < kHeaderBytes) {
    if (fileSize >= SEGY_TEXT_HEADER_SIZE)
      throw scan.error("file ends after the textual header (" + std::to_string(fileSize) +
                       " bytes): no 400-byte binary header");
    throw scan.error("file is " + std::to_string(fileSize) +
                     " bytes, too short for SEG-Y (3200-byte textual + 400-byte binary header)");
  }
  file.handle = segy_open(source.c_str(), "rb");
  if (!file.handle) throw IoError("'" + source + "': " + std::strerror(errno));

  // Byte order: the format code (bytes 3225-3226) must be valid one way or the other.
  char binary[SEGY_BINARY_HEADER_SIZE];
  scan.readBinaryHeader(binary);
  const int msbFormat = segy_format(binary);
  int format = msbFormat;
  if (!sampleTypeOf(msbFormat)) {
    segy_set_format(file.handle, SEGY_LSB);
    scan.readBinaryHeader(binary);
    const int lsbFormat = segy_format(binary);
    if (!sampleTypeOf(lsbFormat)) {
      const int shown =
          (msbFormat > 0 && msbFormat < 256) || lsbFormat <= 0 || lsbFormat >= 256 ? msbFormat : lsbFormat;
      throw scan.error("unsupported sample format code " + std::to_string(shown) +
                       " (binary header bytes 3225-3226), expected 1 (IBM float), 2 (int32), 3 (int16), "
                       "5 (IEEE float) or 8 (int8)");
    }
    format = lsbFormat;
    g.littleEndian = true;
  }
  g.formatCode = format;
  segy_set_format(file.handle, format | (g.littleEndian ? SEGY_LSB : SEGY_MSB));

  file.trace0 = segy_trace0(binary);
  if (file.trace0 < kHeaderBytes)
    throw scan.error("negative number of extended textual headers (binary header bytes 3505-3506)");
  if (fileSize <= file.trace0)
    throw scan.error("no traces: the file ends after its " + std::to_string(file.trace0) + " header bytes");

  char header[SEGY_TRACE_HEADER_SIZE];
  g.samples = segy_samples(binary);
  if (g.samples <= 0) {  // rev 0 files may leave the binary header empty
    scan.readTraceHeader(0, header);
    g.samples = scan.field(header, SEGY_TR_SAMPLE_COUNT, "trace header byte");
    if (g.samples <= 0)
      throw scan.error("no sample count: 0 in the binary header (bytes 3221-3222) and in trace header bytes 115-116");
  }
  file.traceBytes = segy_trsize(format, g.samples);
  const std::int64_t traceSize = SEGY_TRACE_HEADER_SIZE + std::int64_t{file.traceBytes};
  const std::int64_t dataBytes = fileSize - file.trace0;
  if (dataBytes % traceSize != 0)
    throw scan.error(std::to_string(dataBytes) + " bytes of traces are not a whole number of " +
                     std::to_string(traceSize) + "-byte traces (240-byte header + " + std::to_string(g.samples) + " " +
                     segyFormatName(format) + " samples): the file is truncated (last trace has " +
                     std::to_string(dataBytes % traceSize) +
                     " bytes) or the sample count (binary header bytes "
                     "3221-3222) does not match the traces");
  g.traces = dataBytes / traceSize;
  if (g.traces > std::numeric_limits<std::int32_t>::max())
    throw scan.error(std::to_string(g.traces) + " traces, more than segyio's limit of 2^31 - 1");

  float dt = 0;
  if (segy_sample_interval(file.handle, 4000.f, &dt) != SEGY_OK || !(dt > 0)) dt = 4000.f;
  g.sampleIntervalUs = dt;

  // One pass over the trace headers for the line numbers. (Trace header byte 115
  // is not checked: real files keep the uncropped count there, as F3 does.)
  LineKeys keys;
  keys.slow.resize(static_cast<std::size_t>(g.traces));
  keys.fast.resize(static_cast<std::size_t>(g.traces));
  std::vector<std::int32_t>& inl = keys.slow;  // filled as inline/crossline, swapped below if needed
  std::vector<std::int32_t>& xl = keys.fast;
  for (std::int64_t t = 0; t < g.traces; ++t) {
    scan.readTraceHeader(t, header);
    inl[static_cast<std::size_t>(t)] = scan.field(header, options.inlineByte, "--inline-byte");
    xl[static_cast<std::size_t>(t)] = scan.field(header, options.crosslineByte, "--crossline-byte");
    if (t == 0) g.firstSampleMs = scan.field(header, SEGY_TR_DELAY_REC_TIME, "trace header byte");
  }

  // Sorting: which number stays constant from the first trace to the second
  // (inline-sorted when both change: lines of one trace; duplicates are reported below).
  g.sorting = g.traces > 1 && inl[1] != inl[0] && xl[1] == xl[0] ? SegySorting::Crossline : SegySorting::Inline;
  if (g.sorting == SegySorting::Crossline) std::swap(keys.slow, keys.fast);
  const bool inlineSorted = g.sorting == SegySorting::Inline;
  const char* slowName = inlineSorted ? "inline" : "crossline";
  const char* fastName = inlineSorted ? "crossline" : "inline";
  const int slowByte = inlineSorted ? options.inlineByte : options.crosslineByte;
  const auto checkBytes = std::string("(check --inline-byte ") + std::to_string(options.inlineByte) +
                          " and --crossline-byte " + std::to_string(options.crosslineByte) + ")";

  // Lines follow each other monotonically; their numbers give the slow axis.
  SegyLineAxis slow, fast;
  std::vector<std::int64_t> lineStarts{0};
  int direction = 0;
  std::int64_t slowGcd = 0;
  for (std::int64_t t = 1; t < g.traces; ++t) {
    const auto i = static_cast<std::size_t>(t);
    const std::int64_t change = std::int64_t{keys.slow[i]} - keys.slow[i - 1];
    if (change == 0) continue;
    const int sign = change > 0 ? 1 : -1;
    if (direction == 0) direction = sign;
    if (sign != direction)
      throw scan.error(std::string(slowName) + " numbers (trace header byte " + std::to_string(slowByte) +
                       ") are not monotonic in this " + slowName + "-sorted file: trace " + std::to_string(t) +
                       " has " + slowName + " " + std::to_string(keys.slow[i]) + " after " +
                       std::to_string(keys.slow[i - 1]) + " " + checkBytes);
    slowGcd = std::gcd(slowGcd, std::abs(change));
    lineStarts.push_back(t);
  }
  if (direction == 0) direction = 1;  // a single line
  slow.first = keys.slow.front();
  slow.step = static_cast<int>(direction * std::max<std::int64_t>(slowGcd, 1));
  slow.count = static_cast<int>((std::int64_t{keys.slow.back()} - slow.first) / slow.step + 1);

  const auto [fastMin, fastMax] = std::minmax_element(keys.fast.begin(), keys.fast.end());
  std::int64_t fastGcd = 0;
  for (std::int32_t number : keys.fast) fastGcd = std::gcd(fastGcd, std::int64_t{number} - *fastMin);
  fast.first = *fastMin;
  fast.step = static_cast<int>(std::max<std::int64_t>(fastGcd, 1));
  fast.count = static_cast<int>((std::int64_t{*fastMax} - *fastMin) / fast.step + 1);

  const std::int64_t positions = std::int64_t{slow.count} * fast.count;
  if (positions > 4 * g.traces)
    throw scan.error("the inline and crossline numbers make a " +
                     std::to_string(inlineSorted ? slow.count : fast.count) + " x " +
                     std::to_string(inlineSorted ? fast.count : slow.count) + " grid for only " +
                     std::to_string(g.traces) + " traces " + checkBytes);
  g.missingTraces = positions - g.traces;

  // Per line: first trace and count; per trace: index along its line; no duplicates.
  stream->lineFirstTrace_.assign(static_cast<std::size_t>(slow.count), -1);
  stream->lineTraceCount_.assign(static_cast<std::size_t>(slow.count), 0);
  stream->positionOfTrace_.resize(static_cast<std::size_t>(g.traces));
  std::vector<std::int64_t> traceAt(static_cast<std::size_t>(fast.count), -1);
  lineStarts.push_back(g.traces);
  for (std::size_t line = 0; line + 1 < lineStarts.size(); ++line) {
    const std::int64_t begin = lineStarts[line], end = lineStarts[line + 1];
    const int lineIndex = indexOf(keys.slow[static_cast<std::size_t>(begin)], slow);
    stream->lineFirstTrace_[static_cast<std::size_t>(lineIndex)] = begin;
    stream->lineTraceCount_[static_cast<std::size_t>(lineIndex)] = static_cast<std::int32_t>(end - begin);
    for (std::int64_t t = begin; t < end; ++t) {
      const int position = indexOf(keys.fast[static_cast<std::size_t>(t)], fast);
      std::int64_t& previous = traceAt[static_cast<std::size_t>(position)];
      if (previous >= begin)
        throw scan.error("traces " + std::to_string(previous) + " and " + std::to_string(t) + " both have " + slowName +
                         " " + std::to_string(keys.slow[static_cast<std::size_t>(t)]) + " and " + fastName + " " +
                         std::to_string(keys.fast[static_cast<std::size_t>(t)]) + " " + checkBytes);
      previous = t;
      stream->positionOfTrace_[static_cast<std::size_t>(t)] = position;
    }
  }

  // Spacings from CDP coordinates: along the first line, and from it to the last line.
  {
    const std::int64_t a = 0, b = lineStarts[1] - 1, c = lineStarts[lineStarts.size() - 2];
    const auto positionOf = [&](std::int64_t t) {
      return std::array<double, 2>{static_cast<double>(indexOf(keys.slow[static_cast<std::size_t>(t)], slow)),
                                   static_cast<double>(stream->positionOfTrace_[static_cast<std::size_t>(t)])};
    };
    const auto cdp = [&](std::int64_t t) {
      scan.readTraceHeader(t, header);
      return cdpOf(scan, header);
    };
    const auto pa = cdp(a), pb = cdp(b), pc = cdp(c);
    const auto ia = positionOf(a), ib = positionOf(b), ic = positionOf(c);
    std::array<double, 2> alongLine{0, 0}, acrossLines{0, 0};  // world vector per index step
    if (ib[1] != ia[1])
      for (int k = 0; k < 2; ++k) alongLine[k] = (pb[k] - pa[k]) / (ib[1] - ia[1]);
    if (ic[0] != ia[0])
      for (int k = 0; k < 2; ++k) acrossLines[k] = (pc[k] - pa[k] - (ic[1] - ia[1]) * alongLine[k]) / (ic[0] - ia[0]);
    const double along = std::hypot(alongLine[0], alongLine[1]);
    const double across = std::hypot(acrossLines[0], acrossLines[1]);
    g.spacingFromCoordinates = along > 0 || across > 0;
    fast.spacing = along > 0 ? along : 1.0;
    slow.spacing = across > 0 ? across : 1.0;
    for (int k = 0; k < 2; ++k) g.originCdp[k] = pa[k] - ia[0] * acrossLines[k] - ia[1] * alongLine[k];
    const auto& inlineAxis = inlineSorted ? acrossLines : alongLine;
    if (inlineAxis[0] != 0 || inlineAxis[1] != 0) {
      double degrees = std::atan2(inlineAxis[0], inlineAxis[1]) * 180.0 / std::numbers::pi;
      g.rotationDegrees = degrees < 0 ? degrees + 360.0 : degrees;
    }
  }
  g.inlines = inlineSorted ? slow : fast;
  g.crosslines = inlineSorted ? fast : slow;

  VolumeHeader& h = stream->header_;
  h.dims = {g.samples, fast.count, slow.count};
  h.sampleType = *sampleTypeOf(format);
  h.bigEndian = true;  // segyio hands samples over in big-endian order
  h.spacing = {g.sampleIntervalUs / 1000.0, fast.spacing, slow.spacing};
  h.origin = {g.firstSampleMs, 0.0, 0.0};
  h.gridAxis = inlineSorted ? std::array<int, 3>{2, 1, 0} : std::array<int, 3>{2, 0, 1};
  stream->traceBytes_.resize(static_cast<std::size_t>(file.traceBytes));
  return stream;
}

void SegyStream::readSlice(float* out) {
  const std::int64_t line = nextSlice_;
  if (line >= header_.dims[2])
    throw std::out_of_range("'" + source_ + "': all " + std::to_string(header_.dims[2]) + " lines were read");
  const auto samples = static_cast<std::size_t>(geometry_.samples);
  std::fill_n(out, samples * static_cast<std::size_t>(header_.dims[1]), std::numeric_limits<float>::quiet_NaN());
  const std::int64_t first = lineFirstTrace_[static_cast<std::size_t>(line)];
  for (std::int64_t t = first; first >= 0 && t < first + lineTraceCount_[static_cast<std::size_t>(line)]; ++t) {
    if (segy_readtrace(file_->handle, static_cast<int>(t), traceBytes_.data(), file_->trace0, file_->traceBytes) !=
        SEGY_OK)
      throw IoError("'" + source_ + "': cannot read trace " + std::to_string(t));
    const bool ibm = geometry_.formatCode == SEGY_IBM_FLOAT_4_BYTE;
    if (ibm) segy_to_native(SEGY_IBM_FLOAT_4_BYTE, static_cast<long long>(samples), traceBytes_.data());
    float* trace = out + static_cast<std::size_t>(positionOfTrace_[static_cast<std::size_t>(t)]) * samples;
    const std::int64_t bad = convertSamples(reinterpret_cast<const std::byte*>(traceBytes_.data()), header_.sampleType,
                                            ibm ? std::endian::native == std::endian::big : true, samples, trace);
    if (bad >= 0) {
      const int position = positionOfTrace_[static_cast<std::size_t>(t)];
      const bool inlineSorted = geometry_.sorting == SegySorting::Inline;
      const SegyLineAxis& slowAxis = inlineSorted ? geometry_.inlines : geometry_.crosslines;
      const SegyLineAxis& fastAxis = inlineSorted ? geometry_.crosslines : geometry_.inlines;
      const int slowNumber = slowAxis.first + static_cast<int>(line) * slowAxis.step;
      const int fastNumber = fastAxis.first + position * fastAxis.step;
      throw InputError("'" + source_ + "': trace " + std::to_string(t) + " (inline " +
                       std::to_string(inlineSorted ? slowNumber : fastNumber) + ", crossline " +
                       std::to_string(inlineSorted ? fastNumber : slowNumber) + ") sample " + std::to_string(bad) +
                       " is " + (std::isnan(trace[bad]) ? "NaN" : "infinite") + " (samples must be finite)");
    }
  }
  ++nextSlice_;
}

}  // namespace isovdb::io
