// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "generators/segy_writer.h"

#include <segyio/segy.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "isovdb/io/atomic_file.h"

namespace isovdb::samples {

namespace {

/// Big-endian header and sample bytes, swapped per field for little-endian files.
class FieldWriter {
 public:
  FieldWriter(char* buffer, bool littleEndian) : buffer_(buffer), littleEndian_(littleEndian) {}

  /// Writes `value` in `size` bytes at 1-based byte position `byte`.
  void put(int byte, long long value, int size) const {
    char* out = buffer_ + byte - 1;
    for (int k = 0; k < size; ++k) {
      const int shift = 8 * (littleEndian_ ? k : size - 1 - k);
      out[k] = static_cast<char>((static_cast<unsigned long long>(value) >> shift) & 0xff);
    }
  }

 private:
  char* buffer_;
  bool littleEndian_;
};

int sampleBytes(int formatCode) {
  switch (formatCode) {
    case SEGY_SIGNED_SHORT_2_BYTE:
      return 2;
    case SEGY_SIGNED_CHAR_1_BYTE:
      return 1;
    default:
      return 4;
  }
}

long long clampedRound(float value, long long lo, long long hi) {
  return std::clamp(static_cast<long long>(std::llround(value)), lo, hi);
}

/// Encodes `count` floats in the file's format and byte order.
void encodeSamples(const SegyCubeSpec& spec, const float* values, int count, char* out) {
  const int size = sampleBytes(spec.formatCode);
  const FieldWriter writer(out, spec.littleEndian);
  for (int s = 0; s < count; ++s) {
    const int byte = 1 + s * size;
    switch (spec.formatCode) {
      case SEGY_SIGNED_SHORT_2_BYTE:
        writer.put(byte, clampedRound(values[s], -32768, 32767), 2);
        break;
      case SEGY_SIGNED_CHAR_1_BYTE:
        writer.put(byte, clampedRound(values[s], -128, 127), 1);
        break;
      case SEGY_SIGNED_INTEGER_4_BYTE:
        writer.put(
            byte,
            clampedRound(values[s], std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()),
            4);
        break;
      case SEGY_IBM_FLOAT_4_BYTE: {
        float ibm = values[s];
        segy_from_native(SEGY_IBM_FLOAT_4_BYTE, 1, &ibm);  // IBM bits, big-endian in memory
        std::uint32_t bits = 0;
        std::memcpy(&bits, &ibm, 4);
        const auto* be = reinterpret_cast<const unsigned char*>(&bits);
        writer.put(
            byte, (std::uint32_t{be[0]} << 24) | (std::uint32_t{be[1]} << 16) | (std::uint32_t{be[2]} << 8) | be[3], 4);
        break;
      }
      default: {  // IEEE float, and any other code: 4 bytes of IEEE bits
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[s], 4);
        writer.put(byte, bits, 4);
      }
    }
  }
}

}  // namespace

long long writeSegyCube(const std::filesystem::path& path, const SegyCubeSpec& spec, const TraceFunction& trace) {
  io::AtomicFile file(path);
  std::vector<char> text(SEGY_TEXT_HEADER_SIZE, ' ');
  const char banner[] = "C 1 SYNTHETIC CUBE WRITTEN BY ISOVDB (data/generators/segy_writer.cc)";
  std::memcpy(text.data(), banner, sizeof(banner) - 1);
  file.write(text.data(), text.size());

  std::vector<char> binary(SEGY_BINARY_HEADER_SIZE, 0);
  const FieldWriter bin(binary.data() - SEGY_TEXT_HEADER_SIZE, spec.littleEndian);  // 1-based file bytes
  bin.put(SEGY_BIN_INTERVAL, spec.sampleIntervalUs, 2);
  bin.put(SEGY_BIN_SAMPLES, spec.samples, 2);
  bin.put(SEGY_BIN_FORMAT, spec.formatCode, 2);
  bin.put(SEGY_BIN_SORTING_CODE, 4, 2);  // post-stack
  bin.put(SEGY_BIN_SEGY_REVISION, 0x0100, 2);
  bin.put(SEGY_BIN_TRACE_FLAG, 1, 2);  // fixed-length traces
  file.write(binary.data(), binary.size());

  std::vector<char> header(SEGY_TRACE_HEADER_SIZE);
  std::vector<float> values(static_cast<std::size_t>(spec.samples));
  std::vector<char> encoded(static_cast<std::size_t>(spec.samples) * sampleBytes(spec.formatCode));
  const int outer = spec.crosslineSorted ? spec.crosslines : spec.inlines;
  const int inner = spec.crosslineSorted ? spec.inlines : spec.crosslines;
  long long written = 0;
  for (int a = 0; a < outer; ++a) {
    for (int b = 0; b < inner; ++b) {
      const int i = spec.crosslineSorted ? b : a, j = spec.crosslineSorted ? a : b;
      std::fill(values.begin(), values.end(), 0.f);
      if (!trace(i, j, values.data())) continue;
      std::fill(header.begin(), header.end(), 0);
      const FieldWriter th(header.data(), spec.littleEndian);
      th.put(SEGY_TR_SEQ_LINE, written + 1, 4);
      th.put(SEGY_TR_SEQ_FILE, written + 1, 4);
      th.put(spec.inlineByte, spec.firstInline + i * spec.inlineStep, 4);
      th.put(spec.crosslineByte, spec.firstCrossline + j * spec.crosslineStep, 4);
      th.put(SEGY_TR_SOURCE_GROUP_SCALAR, -10, 2);
      th.put(SEGY_TR_CDP_X, std::llround((1000.0 + j * spec.crosslineSpacing) * 10.0), 4);
      th.put(SEGY_TR_CDP_Y, std::llround((2000.0 + i * spec.inlineSpacing) * 10.0), 4);
      th.put(SEGY_TR_DELAY_REC_TIME, spec.delayMs, 2);
      th.put(SEGY_TR_SAMPLE_COUNT, spec.samples, 2);
      th.put(SEGY_TR_SAMPLE_INTER, spec.sampleIntervalUs, 2);
      file.write(header.data(), header.size());
      encodeSamples(spec, values.data(), spec.samples, encoded.data());
      file.write(encoded.data(), encoded.size());
      ++written;
    }
  }
  file.commit();
  return written;
}

}  // namespace isovdb::samples
