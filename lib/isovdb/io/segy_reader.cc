// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/segy_reader.h"

#include <segyio/segy.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <string_view>

#include "isovdb/errors.h"
#include "isovdb/io/path_util.h"

namespace isovdb::io {

struct SegyStream::File {
  segy_file* handle = nullptr;
  long trace0 = 0;         ///< byte offset of the first trace header
  int traceBytes = 0;      ///< sample bytes per trace (without the 240-byte header)
  int extensionBytes = 0;  ///< 240 per trace header extension (SEG-Y rev 2), between the header and the samples
  /// What segyio 1.8 calls a trace's size: it steps over the header extensions as if they were samples.
  int strideBytes() const { return traceBytes + extensionBytes; }
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
    if (segy_traceheader(file_.handle, static_cast<int>(trace), buf, file_.trace0, file_.strideBytes()) != SEGY_OK)
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

/// The binary header as the file holds it: segyio 1.8 knows the fields of revision 1
/// only, so the revision 2 ones (and unsigned counts) are read from these bytes.
class RawBinaryHeader {
 public:
  RawBinaryHeader(const std::string& source, bool littleEndian) : little_(littleEndian) {
    std::ifstream in(source, std::ios::binary);
    in.seekg(SEGY_TEXT_HEADER_SIZE);
    if (!in.read(reinterpret_cast<char*>(bytes_.data()), SEGY_BINARY_HEADER_SIZE))
      throw IoError("'" + source + "': cannot read the binary header");
  }
  /// The byte at file position `byte` (1-based, 3201..3600).
  int byteAt(int byte) const { return bytes_[static_cast<std::size_t>(byte - SEGY_TEXT_HEADER_SIZE - 1)]; }
  std::uint32_t unsigned16(int byte) const { return word(byte, 2); }
  std::int32_t signed16(int byte) const { return static_cast<std::int16_t>(word(byte, 2)); }
  std::int32_t signed32(int byte) const { return static_cast<std::int32_t>(word(byte, 4)); }

 private:
  std::uint32_t word(int byte, int size) const {
    std::uint32_t value = 0;
    for (int i = 0; i < size; ++i) {
      const int at = little_ ? byte + size - 1 - i : byte + i;
      value = (value << 8) | static_cast<std::uint32_t>(byteAt(at));
    }
    return value;
  }
  std::array<unsigned char, SEGY_BINARY_HEADER_SIZE> bytes_{};
  bool little_;
};

/// True when a 3200-byte extended textual header is the ((SEG: EndText)) stanza that
/// ends a variable count (SEG-Y rev 2), in ASCII or EBCDIC, any letter case and spacing.
bool isEndTextStanza(const char* block) {
  // EBCDIC letters, digits, '(', ')', ':' and ' ' as ASCII (the others do not matter here).
  const auto ascii = [](unsigned char c) -> char {
    if (c < 0x80 && c != 0x40 && c != 0x4D && c != 0x5D && c != 0x7A) return static_cast<char>(c);
    static const std::string_view lower = "abcdefghi", lower2 = "jklmnopqr", lower3 = "stuvwxyz";
    if (c >= 0x81 && c <= 0x89) return lower[c - 0x81];
    if (c >= 0x91 && c <= 0x99) return lower2[c - 0x91];
    if (c >= 0xA2 && c <= 0xA9) return lower3[c - 0xA2];
    if (c >= 0xC1 && c <= 0xC9) return lower[c - 0xC1];
    if (c >= 0xD1 && c <= 0xD9) return lower2[c - 0xD1];
    if (c >= 0xE2 && c <= 0xE9) return lower3[c - 0xE2];
    switch (c) {
      case 0x40:
        return ' ';
      case 0x4D:
        return '(';
      case 0x5D:
        return ')';
      case 0x7A:
        return ':';
      default:
        return '?';
    }
  };
  std::string text;
  for (int i = 0; i < 80; ++i) {
    const char c = ascii(static_cast<unsigned char>(block[i]));
    if (c != ' ') text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text.rfind("((seg:endtext))", 0) == 0;
}

/// Extended textual headers counted by the binary header (bytes 3505-3506), or, for
/// -1 (a variable count), up to and including the ((SEG: EndText)) stanza.
int extendedTextHeaderCount(const std::string& source, std::int32_t declared, std::int64_t fileSize) {
  if (declared >= 0) return declared;
  if (declared != -1)
    throw InputError("'" + source + "': " + std::to_string(declared) +
                     " extended textual headers (binary header bytes 3505-3506): expected 0 or more, or -1 for a "
                     "count ended by ((SEG: EndText))");
  std::ifstream in(source, std::ios::binary);
  std::array<char, SEGY_TEXT_HEADER_SIZE> block{};
  for (int count = 1;; ++count) {
    const std::int64_t at = std::int64_t{SEGY_TEXT_HEADER_SIZE} * count + SEGY_BINARY_HEADER_SIZE;
    in.seekg(at);
    if (at + SEGY_TEXT_HEADER_SIZE > fileSize || !in.read(block.data(), SEGY_TEXT_HEADER_SIZE))
      throw InputError("'" + source +
                       "': the binary header (bytes 3505-3506) says the extended textual headers end with a "
                       "((SEG: EndText)) stanza, but the file has none");
    if (isEndTextStanza(block.data())) return count;
  }
}

struct LineKeys {
  std::vector<std::int32_t> slow, fast;  ///< per trace: number of its line, and along the line
};

/// Index along a line axis whose numbers are first + i * step.
int indexOf(int number, const SegyLineAxis& axis) {
  return static_cast<int>((std::int64_t{number} - axis.first) / axis.step);
}

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

  const RawBinaryHeader raw(source, g.littleEndian);
  g.revision = raw.byteAt(3501);
  g.revisionMinor = raw.byteAt(3502);
  g.extendedTextHeaders = extendedTextHeaderCount(source, raw.signed16(3505), fileSize);
  g.extendedTextHeaderCountVariable = raw.signed16(3505) == -1;
  // Bytes 3507-3508 are unassigned before revision 2 (old files may hold anything there).
  g.traceHeaderExtensions = g.revision >= 2 ? static_cast<int>(raw.unsigned16(3507)) : 0;
  file.trace0 = kHeaderBytes + std::int64_t{SEGY_TEXT_HEADER_SIZE} * g.extendedTextHeaders;
  file.extensionBytes = SEGY_TRACE_HEADER_SIZE * g.traceHeaderExtensions;
  if (fileSize <= file.trace0)
    throw scan.error("no traces: the file ends after its " + std::to_string(file.trace0) + " header bytes");

  char header[SEGY_TRACE_HEADER_SIZE];
  // The count is unsigned (60000 samples are valid); revision 2 may put it in bytes 3269-3272.
  const std::uint32_t binarySamples = raw.unsigned16(3221);
  g.samples = static_cast<int>(binarySamples);
  if (g.samples == 0 && g.revision >= 2 && raw.signed32(3269) > 0) g.samples = raw.signed32(3269);
  if (g.samples == 0) {  // rev 0 files may leave the binary header empty
    scan.readTraceHeader(0, header);
    g.samples = scan.field(header, SEGY_TR_SAMPLE_COUNT, "trace header byte") & 0xFFFF;
    if (g.samples == 0)
      throw scan.error("no sample count: binary header bytes 3221-3222 hold 0 and trace header bytes 115-116 hold 0");
  }
  constexpr int kMaxSamples = 1 << 26;  // 256 MiB per trace: beyond it the header is wrong, not the survey
  if (g.samples > kMaxSamples)
    throw scan.error(std::to_string(g.samples) + " samples per trace (binary header bytes 3269-3272): more than " +
                     std::to_string(kMaxSamples));
  file.traceBytes = segy_trsize(format, g.samples);
  const std::int64_t traceSize = SEGY_TRACE_HEADER_SIZE + std::int64_t{file.extensionBytes} + file.traceBytes;
  const std::int64_t dataBytes = fileSize - file.trace0;
  const std::string extensions = g.traceHeaderExtensions > 0
                                     ? " + " + std::to_string(g.traceHeaderExtensions) +
                                           " trace header extensions of 240 bytes (binary header bytes 3507-3508)"
                                     : "";
  if (dataBytes % traceSize != 0)
    throw scan.error(std::to_string(dataBytes) + " bytes of traces are not a whole number of " +
                     std::to_string(traceSize) + "-byte traces (240-byte header" + extensions + " + " +
                     std::to_string(g.samples) + " " + segyFormatName(format) +
                     " samples): the file is truncated (last trace has " + std::to_string(dataBytes % traceSize) +
                     " bytes) or the sample count (binary header bytes 3221-3222) does not match the traces");
  g.traces = dataBytes / traceSize;
  if (g.traces > std::numeric_limits<std::int32_t>::max())
    throw scan.error(std::to_string(g.traces) + " traces, more than segyio's limit of 2^31 - 1");

  // Sample interval as segyio 2 chooses it: a header's non-positive value is ignored,
  // and two positive values that disagree give the fallback (4 ms).
  scan.readTraceHeader(0, header);
  const int binaryInterval = raw.signed16(3217);
  const int traceInterval = static_cast<std::int16_t>(scan.field(header, SEGY_TR_SAMPLE_INTER, "trace header byte"));
  g.sampleIntervalUs = 4000.0;
  if (binaryInterval > 0 && (traceInterval <= 0 || traceInterval == binaryInterval))
    g.sampleIntervalUs = binaryInterval;
  else if (binaryInterval <= 0 && traceInterval > 0)
    g.sampleIntervalUs = traceInterval;

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
    if (t == 0) {
      // The delay (bytes 109-110) is scaled by bytes 215-216 like a coordinate: > 0 multiplies, < 0 divides.
      const int scalar = scan.field(header, SEGY_TR_SCALAR_TRACE_HEADER, "trace header byte");
      const double factor = scalar == 0 ? 1.0 : scalar > 0 ? scalar : 1.0 / -scalar;
      g.firstSampleMs = scan.field(header, SEGY_TR_DELAY_REC_TIME, "trace header byte") * factor;
    }
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
  const auto [fastMin, fastMax] = std::minmax_element(keys.fast.begin(), keys.fast.end());
  std::int64_t fastGcd = 0;
  for (std::int32_t number : keys.fast) fastGcd = std::gcd(fastGcd, std::int64_t{number} - *fastMin);
  // Counts and steps in 64 bits first: line numbers may span more than an int.
  const std::int64_t slowStep = direction * std::max<std::int64_t>(slowGcd, 1);
  const std::int64_t slowCount = (std::int64_t{keys.slow.back()} - keys.slow.front()) / slowStep + 1;
  const std::int64_t fastStep = std::max<std::int64_t>(fastGcd, 1);
  const std::int64_t fastCount = (std::int64_t{*fastMax} - *fastMin) / fastStep + 1;
  constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
  if (std::abs(slowStep) > kIntMax || fastStep > kIntMax || slowCount > kIntMax || fastCount > kIntMax)
    throw scan.error(std::string(slowName) + " numbers " + std::to_string(keys.slow.front()) + ".." +
                     std::to_string(keys.slow.back()) + " and " + fastName + " numbers " + std::to_string(*fastMin) +
                     ".." + std::to_string(*fastMax) + " step or count beyond 2^31 - 1 " + checkBytes);
  if (slowCount * fastCount > 4 * g.traces)
    throw scan.error("the inline and crossline numbers make a " + std::to_string(inlineSorted ? slowCount : fastCount) +
                     " x " + std::to_string(inlineSorted ? fastCount : slowCount) + " grid for only " +
                     std::to_string(g.traces) + " traces " + checkBytes);
  slow.first = keys.slow.front();
  slow.step = static_cast<int>(slowStep);
  slow.count = static_cast<int>(slowCount);
  fast.first = *fastMin;
  fast.step = static_cast<int>(fastStep);
  fast.count = static_cast<int>(fastCount);
  const std::int64_t positions = slowCount * fastCount;
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
                         std::to_string(keys.fast[static_cast<std::size_t>(t)]) +
                         ": several traces per bin, as in a pre-stack file (offsets, shot or CDP gathers); isovdb "
                         "reads post-stack cubes (one trace per inline and crossline): stack the gathers or keep "
                         "one offset first, or, if the lines are numbered elsewhere, " +
                         checkBytes.substr(1, checkBytes.size() - 2));
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
    // segyio 1.8 knows no header extensions: the samples start after them, and the stride steps over them.
    if (segy_readsubtr(file_->handle, static_cast<int>(t), 0, geometry_.samples, 1, traceBytes_.data(), nullptr,
                       file_->trace0 + file_->extensionBytes, file_->strideBytes()) != SEGY_OK)
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
